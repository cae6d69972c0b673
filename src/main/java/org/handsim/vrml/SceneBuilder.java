package org.handsim.vrml;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.nio.file.Path;
import org.jogamp.java3d.Appearance;
import org.jogamp.java3d.Background;
import org.jogamp.java3d.BoundingSphere;
import org.jogamp.java3d.BranchGroup;
import org.jogamp.java3d.DirectionalLight;
import org.jogamp.java3d.ExponentialFog;
import org.jogamp.java3d.Fog;
import org.jogamp.java3d.Geometry;
import org.jogamp.java3d.Group;
import org.jogamp.java3d.Light;
import org.jogamp.java3d.LinearFog;
import org.jogamp.java3d.Link;
import org.jogamp.java3d.Material;
import org.jogamp.java3d.Node;
import org.jogamp.java3d.PointLight;
import org.jogamp.java3d.PolygonAttributes;
import org.jogamp.java3d.Shape3D;
import org.jogamp.java3d.SharedGroup;
import org.jogamp.java3d.SpotLight;
import org.jogamp.java3d.Switch;
import org.jogamp.java3d.Transform3D;
import org.jogamp.java3d.TransformGroup;
import org.jogamp.java3d.TransparencyAttributes;
import org.jogamp.java3d.loaders.Loader;
import org.jogamp.vecmath.AxisAngle4d;
import org.jogamp.vecmath.Color3f;
import org.jogamp.vecmath.Point3d;
import org.jogamp.vecmath.Point3f;
import org.jogamp.vecmath.Vector3d;
import org.jogamp.vecmath.Vector3f;

/**
 * Builds the Java3D scene graph from parsed VRML nodes.
 *
 * <table>
 *   <caption>VRML97 node ⇒ Java3D</caption>
 *   <tr><td>Group, Collision, Anchor, Billboard</td><td>{@link Group} (Collision's proxy, Anchor's
 *       link and Billboard's rotation toward the viewer have no geometric effect here)</td></tr>
 *   <tr><td>Transform</td><td>{@link TransformGroup} with T·C·R·SR·S·SR⁻¹·C⁻¹ (clause 6.52)</td></tr>
 *   <tr><td>Switch</td><td>{@link Switch}, whichChoice kept (out of range: nothing)</td></tr>
 *   <tr><td>LOD</td><td>{@link Switch} of the levels showing the finest (or the chosen) level</td></tr>
 *   <tr><td>Shape</td><td>{@link Shape3D}: geometry as {@link org.jogamp.java3d.IndexedTriangleArray},
 *       Appearance with Material (diffuse colour, transparency, ...), back faces shown for
 *       {@code solid FALSE}</td></tr>
 *   <tr><td>Inline</td><td>{@link Link} to a {@link SharedGroup} holding the file, built once
 *       per file however often it is inlined</td></tr>
 *   <tr><td>Viewpoint, lights, Background, Fog</td><td>TransformGroup / Light / Background / Fog,
 *       also listed in the Scene (top-level content only: Java3D forbids some of them below
 *       a SharedGroup)</td></tr>
 *   <tr><td>sensors, interpolators, Script, Sound, NavigationInfo, TimeSensor</td><td>ignored</td></tr>
 * </table>
 *
 * <p><b>Sharing.</b> A node USE'd in several places is built once: scene-graph nodes go into a
 * {@link SharedGroup} referenced by one {@link Link} per use (Java3D allows a node only one
 * parent), node components (Appearance, Material, Geometry) are simply shared.
 *
 * <p><b>Inlines</b> are not built recursively: each Inline leaves an empty Group and a work
 * item; the work list is processed after the file, so Inline chains cost no stack, and a file
 * that inlines one of its own ancestors is reported as a cycle.
 */
final class SceneBuilder {
    private final LoadSession s;
    private final VrmlScene scene;
    private final GeometryBuilder geo;
    private final IdentityHashMap<VrmlNode, Integer> refs = new IdentityHashMap<>();
    private final IdentityHashMap<VrmlNode, SharedGroup> shared = new IdentityHashMap<>();
    private final IdentityHashMap<VrmlNode, Object> built = new IdentityHashMap<>();
    private final IdentityHashMap<VrmlNode, Geometry> geometries = new IdentityHashMap<>();
    private final IdentityHashMap<VrmlNode, Appearance[]> appearances = new IdentityHashMap<>();
    private final IdentityHashMap<VrmlNode, Material> materials = new IdentityHashMap<>();
    private final IdentityHashMap<VrmlNode, Boolean> texturesChecked = new IdentityHashMap<>();
    private final Map<Path, SharedGroup> inlineGroups = new HashMap<>();
    private final ArrayDeque<Pending> pending = new ArrayDeque<>();
    private Appearance defaultAppearance, defaultAppearanceTwoSided;
    private int sharedLevel;
    private List<Path> ancestry = new ArrayList<>();

    /** An Inline waiting to be built: the empty Group it fills, and the files inlined above it. */
    private record Pending(Group slot, VrmlNode inline, List<Path> ancestry) {}

    SceneBuilder(LoadSession s, VrmlScene scene) {
        this.s = s;
        this.scene = scene;
        this.geo = new GeometryBuilder(s);
    }

    /** Builds the top-level file, then every Inline; names the top file's DEFs in the scene. */
    BranchGroup build(LoadSession.ParsedFile top) {
        BranchGroup root = new BranchGroup();
        allowRead(root);
        root.setCapability(BranchGroup.ALLOW_DETACH);
        if (top.text().path != null) ancestry.add(top.text().path);
        addAll(root, top.roots());
        for (Map.Entry<String, VrmlNode> e : top.defs().entrySet()) {
            Object o = e.getValue() == null ? null : built.get(e.getValue());
            if (o != null) scene.addNamedObject(e.getKey(), o);
        }
        sharedLevel = 1;
        while (!pending.isEmpty()) inline(pending.poll());
        return root;
    }

    private void addAll(Group g, List<VrmlNode> roots) {
        countRefs(roots);
        for (VrmlNode n : roots) {
            Node c = child(n, 1);
            if (c != null) g.addChild(c);
        }
    }

    /** Counts the parents of every node reachable from {@code roots} (iteratively). */
    private void countRefs(List<VrmlNode> roots) {
        ArrayDeque<VrmlNode> stack = new ArrayDeque<>();
        for (VrmlNode r : roots) {
            if (refs.merge(r, 1, Integer::sum) == 1) stack.push(r);
        }
        while (!stack.isEmpty()) {
            VrmlNode n = stack.pop();
            for (int i = 0; i < n.type.size(); i++) {
                Object v = n.get(i);
                if (v instanceof VrmlNode) {
                    if (refs.merge((VrmlNode) v, 1, Integer::sum) == 1) stack.push((VrmlNode) v);
                } else if (v instanceof VrmlNode[]) {
                    for (VrmlNode c : (VrmlNode[]) v) {
                        if (refs.merge(c, 1, Integer::sum) == 1) stack.push(c);
                    }
                }
            }
        }
    }

    private static boolean isGraphNode(String t) {
        switch (t) {
            case "Group": case "Transform": case "Collision": case "Anchor": case "Billboard": case "Switch": case "LOD":
            case "Shape": case "Inline":
                return true;
            default:
                return false;
        }
    }

    /** A child: shared through a SharedGroup if used more than once. */
    private Node child(VrmlNode n, int depth) {
        if (depth > s.maxDepth) {
            throw n.text.error(n.offset, "scene nested more than " + s.maxDepth + " levels deep (limit of this loader)");
        }
        if (refs.getOrDefault(n, 1) > 1 && isGraphNode(n.type.name)) {
            SharedGroup sg = shared.get(n);
            if (sg == null) {
                sg = new SharedGroup();
                allowRead(sg);
                shared.put(n, sg);
                sharedLevel++;
                try {
                    Node inner = node(n, depth);
                    if (inner != null) sg.addChild(inner);
                } finally {
                    sharedLevel--;
                }
            }
            Link l = new Link(sg);
            l.setCapability(Link.ALLOW_SHARED_GROUP_READ);
            return l;
        }
        return node(n, depth);
    }

    private Node node(VrmlNode n, int depth) {
        Node out;
        String t = n.type.name;
        switch (t) {
            case "Group": case "Collision": case "Anchor": case "Billboard": {
                Group g = new Group();
                allowRead(g);
                children(g, n.getNodes("children"), depth);
                out = g;
                break;
            }
            case "Transform": {
                TransformGroup g = new TransformGroup(transform(n));
                allowRead(g);
                g.setCapability(TransformGroup.ALLOW_TRANSFORM_READ);
                children(g, n.getNodes("children"), depth);
                out = g;
                break;
            }
            case "Switch": {
                Switch sw = new Switch();
                allowRead(sw);
                sw.setCapability(Switch.ALLOW_SWITCH_READ);
                VrmlNode[] kids = n.getNodes("choice");
                placeholders(sw, kids, depth);
                int which = n.getInt("whichChoice");
                sw.setWhichChild(which >= 0 && which < kids.length ? which : Switch.CHILD_NONE);
                out = sw;
                break;
            }
            case "LOD": {
                Switch sw = new Switch();
                allowRead(sw);
                sw.setCapability(Switch.ALLOW_SWITCH_READ);
                VrmlNode[] kids = n.getNodes("level");
                placeholders(sw, kids, depth);
                sw.setWhichChild(kids.length == 0 ? Switch.CHILD_NONE : Math.min(s.lodLevel, kids.length - 1));
                out = sw;
                break;
            }
            case "Shape":
                out = shape(n);
                break;
            case "Inline": {
                Group slot = new Group();
                allowRead(slot);
                pending.add(new Pending(slot, n, ancestry));
                out = slot;
                break;
            }
            case "Viewpoint":
                out = viewpoint(n);
                break;
            case "DirectionalLight": case "PointLight": case "SpotLight":
                out = light(n);
                break;
            case "Background":
                out = background(n);
                break;
            case "Fog":
                out = fog(n);
                break;
            case "WorldInfo": {
                String title = (String) n.get("title");
                if (sharedLevel == 0 && title != null && !title.isEmpty()) scene.addDescription(title);
                out = null;
                break;
            }
            case "NavigationInfo": case "Script": case "Sound": case "TimeSensor": case "TouchSensor": case "PlaneSensor":
            case "CylinderSensor": case "SphereSensor": case "ProximitySensor": case "VisibilitySensor":
            case "ColorInterpolator": case "CoordinateInterpolator": case "NormalInterpolator": case "OrientationInterpolator":
            case "PositionInterpolator": case "ScalarInterpolator":
                out = null; // behaviour only: no geometry
                break;
            default:
                s.warn(n.text, n.offset, n.describe() + " is not a child node (it cannot appear in a children list); ignored");
                out = null;
        }
        if (out != null) {
            if (n.defName != null) out.setName(n.defName);
            built.put(n, out);
        }
        return out;
    }

    private void children(Group g, VrmlNode[] kids, int depth) {
        for (VrmlNode k : kids) {
            Node c = child(k, depth + 1);
            if (c != null) g.addChild(c);
        }
    }

    /** Children of a Switch/LOD: an empty Group stands in for a child without content, so indices stay. */
    private void placeholders(Group g, VrmlNode[] kids, int depth) {
        for (VrmlNode k : kids) {
            Node c = child(k, depth + 1);
            if (c == null) {
                Group empty = new Group();
                allowRead(empty);
                c = empty;
            }
            g.addChild(c);
        }
    }

    private static void allowRead(Group g) {
        g.setCapability(Group.ALLOW_CHILDREN_READ);
    }

    /** Transform = T × C × R × SR × S × SR⁻¹ × C⁻¹ (ISO/IEC 14772-1, 6.52). */
    static Transform3D transform(VrmlNode n) {
        float[] tr = n.getFloats("translation"), c = n.getFloats("center"), r = n.getFloats("rotation");
        float[] sc = n.getFloats("scale"), so = n.getFloats("scaleOrientation");
        Transform3D m = new Transform3D();
        m.setTranslation(new Vector3d(tr[0] + c[0], tr[1] + c[1], tr[2] + c[2]));
        m.mul(rotation(r));
        if (sc[0] != 1 || sc[1] != 1 || sc[2] != 1) {
            Transform3D sr = rotation(so);
            m.mul(sr);
            Transform3D s = new Transform3D();
            s.setScale(new Vector3d(sc[0], sc[1], sc[2]));
            m.mul(s);
            sr.transpose();
            m.mul(sr);
        }
        if (c[0] != 0 || c[1] != 0 || c[2] != 0) {
            Transform3D back = new Transform3D();
            back.setTranslation(new Vector3d(-c[0], -c[1], -c[2]));
            m.mul(back);
        }
        return m;
    }

    private static Transform3D rotation(float[] r) {
        Transform3D t = new Transform3D();
        double l = Math.sqrt((double) r[0] * r[0] + (double) r[1] * r[1] + (double) r[2] * r[2]);
        if (l > 0 && r[3] != 0) t.setRotation(new AxisAngle4d(r[0] / l, r[1] / l, r[2] / l, r[3]));
        return t;
    }

    // ------------------------------------------------------------------ shapes

    private Node shape(VrmlNode n) {
        VrmlNode g = n.getNode("geometry");
        if (g == null) return null;
        Geometry geom = geometry(g);
        if (geom == null) return null;
        Appearance ap = appearance(n.getNode("appearance"), solid(g));
        Shape3D sh = new Shape3D(geom, ap);
        sh.setCapability(Shape3D.ALLOW_GEOMETRY_READ);
        sh.setCapability(Shape3D.ALLOW_APPEARANCE_READ);
        return sh;
    }

    private Geometry geometry(VrmlNode g) {
        if (geometries.containsKey(g)) return geometries.get(g);
        TriGeometry t = null;
        Geometry out = null;
        int div = s.divisions;
        switch (g.type.name) {
            case "IndexedFaceSet":
                t = geo.indexedFaceSet(g);
                break;
            case "Box": {
                float[] sz = g.getFloats("size");
                t = Primitives.box(sz[0], sz[1], sz[2]);
                break;
            }
            case "Sphere":
                t = Primitives.sphere(g.getFloat("radius"), div);
                break;
            case "Cylinder":
                t = Primitives.cylinder(g.getFloat("radius"), g.getFloat("height"), div, g.getBool("side"), g.getBool("top"), g.getBool("bottom"));
                break;
            case "Cone":
                t = Primitives.cone(g.getFloat("bottomRadius"), g.getFloat("height"), div, g.getBool("side"), g.getBool("bottom"));
                break;
            case "ElevationGrid":
                t = geo.elevationGrid(g);
                break;
            case "Extrusion":
                t = geo.extrusion(g);
                break;
            case "IndexedLineSet":
                out = geo.indexedLineSet(g);
                break;
            case "PointSet":
                out = geo.pointSet(g);
                break;
            case "Text":
                s.warn(g.text, g.offset, "Text is not turned into geometry by this loader; skipped");
                break;
            default:
                s.warn(g.text, g.offset, "geometry of Shape is a " + g.type.name + ", not a geometry node; ignored");
        }
        if (t != null) {
            if (!s.normals) {
                t.normals = null;
                t.normalIndex = null;
            }
            out = t.toJava3D();
        }
        if (out != null && g.defName != null) out.setName(g.defName);
        geometries.put(g, out);
        if (out != null) built.put(g, out);
        return out;
    }

    /** The {@code solid} field of IndexedFaceSet, ElevationGrid and Extrusion; the primitives are solid. */
    private static boolean solid(VrmlNode g) {
        int i = g.type.indexOf("solid");
        return i < 0 || (Boolean) g.get(i);
    }

    private Appearance appearance(VrmlNode a, boolean solid) {
        int k = solid ? 0 : 1;
        if (a == null) {
            if (solid) {
                if (defaultAppearance == null) defaultAppearance = newAppearance(null, true);
                return defaultAppearance;
            }
            if (defaultAppearanceTwoSided == null) defaultAppearanceTwoSided = newAppearance(null, false);
            return defaultAppearanceTwoSided;
        }
        Appearance[] pair = appearances.computeIfAbsent(a, x -> new Appearance[2]);
        if (pair[k] == null) {
            pair[k] = newAppearance(a, solid);
            if (a.defName != null) pair[k].setName(a.defName);
            built.putIfAbsent(a, pair[k]);
        }
        return pair[k];
    }

    private Appearance newAppearance(VrmlNode a, boolean solid) {
        Appearance ap = new Appearance();
        ap.setCapability(Appearance.ALLOW_MATERIAL_READ);
        ap.setCapability(Appearance.ALLOW_TRANSPARENCY_ATTRIBUTES_READ);
        if (!solid) {
            PolygonAttributes pa = new PolygonAttributes(PolygonAttributes.POLYGON_FILL, PolygonAttributes.CULL_NONE, 0, true);
            ap.setPolygonAttributes(pa);
        }
        if (a == null) return ap;
        if (!a.type.name.equals("Appearance")) {
            s.warn(a.text, a.offset, "appearance of Shape is a " + a.type.name + ", not an Appearance; ignored");
            return ap;
        }
        VrmlNode m = a.getNode("material");
        if (m != null) {
            if (m.type.name.equals("Material")) {
                ap.setMaterial(material(m));
                float tr = m.getFloat("transparency");
                if (tr > 0) ap.setTransparencyAttributes(new TransparencyAttributes(TransparencyAttributes.NICEST, Math.min(1f, tr)));
            } else {
                s.warn(m.text, m.offset, "material of Appearance is a " + m.type.name + ", not a Material; ignored");
            }
        }
        VrmlNode tex = a.getNode("texture");
        if (tex != null) checkTexture(tex);
        return ap;
    }

    private Material material(VrmlNode m) {
        Material mat = materials.get(m);
        if (mat != null) return mat;
        float[] d = m.getFloats("diffuseColor"), e = m.getFloats("emissiveColor"), sp = m.getFloats("specularColor");
        float amb = m.getFloat("ambientIntensity");
        float shin = Math.max(1f, Math.min(128f, m.getFloat("shininess") * 128f));
        mat = new Material(new Color3f(d[0] * amb, d[1] * amb, d[2] * amb), new Color3f(e[0], e[1], e[2]),
            new Color3f(d[0], d[1], d[2]), new Color3f(sp[0], sp[1], sp[2]), shin);
        mat.setCapability(Material.ALLOW_COMPONENT_READ);
        if (m.defName != null) mat.setName(m.defName);
        materials.put(m, mat);
        built.put(m, mat);
        return mat;
    }

    /** Textures are located (a missing one is a warning), not applied: geometry does not need them. */
    private void checkTexture(VrmlNode tex) {
        if (texturesChecked.put(tex, Boolean.TRUE) != null) return;
        String t = tex.type.name;
        if (t.equals("PixelTexture")) return;
        if (!t.equals("ImageTexture") && !t.equals("MovieTexture")) {
            s.warn(tex.text, tex.offset, "texture of Appearance is a " + t + ", not a texture node; ignored");
            return;
        }
        List<String> reasons = new ArrayList<>();
        if (s.resolveFirst(tex.text, tex.getStrings("url"), reasons) != null) return;
        s.warn(tex.text, tex.offsetOf("url"), "texture not available (" + (reasons.isEmpty() ? "no url" : String.join("; ", reasons))
            + "); the shape loads without it");
    }

    // ------------------------------------------------------------------ view, lights, background

    private Node viewpoint(VrmlNode n) {
        if (sharedLevel > 0 || (s.flags & Loader.LOAD_VIEW_GROUPS) == 0) return null;
        float[] p = n.getFloats("position"), o = n.getFloats("orientation");
        Transform3D t = rotation(o);
        t.setTranslation(new Vector3d(p[0], p[1], p[2]));
        TransformGroup tg = new TransformGroup(t);
        tg.setCapability(TransformGroup.ALLOW_TRANSFORM_READ);
        scene.addViewGroup(tg);
        scene.addHorizontalFOV(n.getFloat("fieldOfView"));
        return tg;
    }

    private static final BoundingSphere EVERYWHERE = new BoundingSphere(new Point3d(), Double.MAX_VALUE / 4);

    private Node light(VrmlNode n) {
        if (sharedLevel > 0 || (s.flags & Loader.LOAD_LIGHT_NODES) == 0) return null;
        float[] c = n.getFloats("color");
        float in = n.getFloat("intensity");
        Color3f col = new Color3f(c[0] * in, c[1] * in, c[2] * in);
        Light l;
        switch (n.type.name) {
            case "DirectionalLight": {
                float[] d = n.getFloats("direction");
                l = new DirectionalLight(col, new Vector3f(d[0], d[1], d[2]));
                break;
            }
            case "PointLight": {
                float[] p = n.getFloats("location"), a = n.getFloats("attenuation");
                l = new PointLight(col, new Point3f(p[0], p[1], p[2]), new Point3f(a[0], a[1], a[2]));
                break;
            }
            default: {
                float[] p = n.getFloats("location"), a = n.getFloats("attenuation"), d = n.getFloats("direction");
                l = new SpotLight(col, new Point3f(p[0], p[1], p[2]), new Point3f(a[0], a[1], a[2]), new Vector3f(d[0], d[1], d[2]),
                    n.getFloat("cutOffAngle"), 0f);
            }
        }
        l.setEnable(n.getBool("on"));
        l.setInfluencingBounds(EVERYWHERE);
        scene.addLightNode(l);
        return l;
    }

    private Node background(VrmlNode n) {
        if (sharedLevel > 0 || (s.flags & Loader.LOAD_BACKGROUND_NODES) == 0) return null;
        float[] sky = n.getFloats("skyColor");
        Background b = new Background(sky.length >= 3 ? new Color3f(sky[0], sky[1], sky[2]) : new Color3f());
        b.setApplicationBounds(EVERYWHERE);
        scene.addBackgroundNode(b);
        return b;
    }

    private Node fog(VrmlNode n) {
        if (sharedLevel > 0 || (s.flags & Loader.LOAD_FOG_NODES) == 0) return null;
        float[] c = n.getFloats("color");
        float range = n.getFloat("visibilityRange");
        if (!(range > 0)) return null;
        Fog f = "EXPONENTIAL".equals(n.get("fogType"))
            ? new ExponentialFog(new Color3f(c[0], c[1], c[2]), 1f / range)
            : new LinearFog(new Color3f(c[0], c[1], c[2]), 0, range);
        f.setInfluencingBounds(EVERYWHERE);
        scene.addFogNode(f);
        return f;
    }

    // ------------------------------------------------------------------ Inline

    private void inline(Pending p) {
        VrmlNode n = p.inline();
        String[] urls = n.getStrings("url");
        if (urls.length == 0) {
            s.warn(n.text, n.offset, "Inline without url; empty");
            return;
        }
        List<String> reasons = new ArrayList<>();
        LoadSession.Resolved r = s.resolveFirst(n.text, urls, reasons);
        int at = n.offsetOf("url");
        if (r == null) throw n.text.error(at, "Inline " + String.join("; ", reasons));
        if (p.ancestry().contains(r.real())) {
            throw n.text.error(at, "Inline cycle: '" + r.display() + "' is already being inlined on this path");
        }
        SharedGroup sg = inlineGroups.get(r.real());
        if (sg == null) {
            LoadSession.ParsedFile f = s.parseFile(r, n.text, at);
            sg = new SharedGroup();
            allowRead(sg);
            inlineGroups.put(r.real(), sg);
            List<Path> saved = ancestry;
            ancestry = new ArrayList<>(p.ancestry());
            ancestry.add(r.real());
            try {
                addAll(sg, f.roots());
            } finally {
                ancestry = saved;
            }
        }
        Link l = new Link(sg);
        l.setCapability(Link.ALLOW_SHARED_GROUP_READ);
        p.slot().addChild(l);
    }
}
