package org.handsim.gui;

import java.awt.GraphicsConfiguration;
import java.lang.management.ManagementFactory;
import java.util.BitSet;
import java.util.Iterator;
import java.util.concurrent.atomic.AtomicLong;
import org.handsim.grasp.FrictionCone;
import org.handsim.math.RigidTransform;
import org.handsim.mesh.TriangleMesh;
import org.jogamp.java3d.AmbientLight;
import org.jogamp.java3d.Appearance;
import org.jogamp.java3d.Background;
import org.jogamp.java3d.Behavior;
import org.jogamp.java3d.BoundingSphere;
import org.jogamp.java3d.BranchGroup;
import org.jogamp.java3d.Canvas3D;
import org.jogamp.java3d.ColoringAttributes;
import org.jogamp.java3d.DirectionalLight;
import org.jogamp.java3d.GeometryArray;
import org.jogamp.java3d.LineArray;
import org.jogamp.java3d.LineAttributes;
import org.jogamp.java3d.Material;
import org.jogamp.java3d.Node;
import org.jogamp.java3d.PolygonAttributes;
import org.jogamp.java3d.RenderingAttributes;
import org.jogamp.java3d.Shape3D;
import org.jogamp.java3d.Switch;
import org.jogamp.java3d.Transform3D;
import org.jogamp.java3d.TransformGroup;
import org.jogamp.java3d.TransparencyAttributes;
import org.jogamp.java3d.TriangleArray;
import org.jogamp.java3d.View;
import org.jogamp.java3d.WakeupOnElapsedFrames;
import org.jogamp.java3d.utils.behaviors.vp.OrbitBehavior;
import org.jogamp.java3d.utils.geometry.Sphere;
import org.jogamp.java3d.utils.universe.SimpleUniverse;
import org.jogamp.vecmath.Color3f;
import org.jogamp.vecmath.Point3d;
import org.jogamp.vecmath.Vector3d;
import org.jogamp.vecmath.Vector3f;

/**
 * The Java3D view of the hand, the object and the contacts: a {@link Canvas3D} in a
 * {@link SimpleUniverse}, lit by an ambient and two directional lights, with mouse orbit
 * (left drag), zoom (middle drag or wheel) and pan (right drag) from {@link OrbitBehavior}.
 *
 * <h2>Scene graph</h2>
 * <pre>
 * BranchGroup root
 *  ├─ Background, lights, OrbitBehavior bounds, the FPS spin behaviour
 *  └─ TransformGroup worldToVworld  (Rx(−90°): the world's z axis is "up" on the screen)
 *      └─ TransformGroup spin        (turned only while the frame rate is measured)
 *          ├─ Switch hand
 *          │   ├─ TransformGroup palm        ← world ← palm          (palm mesh, floor grid)
 *          │   └─ TransformGroup link[k][j]  ← frame {kj} in the world (link j mesh)
 *          ├─ Switch object  └─ TransformGroup object ← world ← object · scale (a free object: its pose each frame)
 *          ├─ Switch contacts (per-child mask)  spheres at the contact points, one set of lines
 *          │                                   of normals (outward, 35 mm), drawn over the scene
 *          ├─ Switch cones    one set of lines: each contact's linearised friction cone, in its
 *          │                  finger's colour, drawn over the scene (View ▸ Friction cones)
 *          └─ Switch markers  the inverse-kinematics target and its closest reachable point
 * </pre>
 * One mesh per link type serves all three fingers: the nine link {@link Shape3D}s share three
 * geometries (NodeComponents may be shared; nodes may not). Each link mesh is in its own DH
 * frame {kj} (vrml/README.md), so placing it is one {@code setTransform} of frame j of
 * {@code Snapshot.FingerSnapshot#framesWorld()}.
 *
 * <h2>Threads</h2>
 * Only the event dispatch thread changes the scene graph ({@link #show}, {@link #setObject},
 * {@link #setVisible}); Java3D renders on its own threads. The lines that change with every
 * pose (normals, cones) are written only into geometry that is not live and then swapped in
 * ({@link DoubleBufferedLines} says why: Java3D's threads can die on writes to live geometry).
 * {@link #measureFps} blocks and must not be called on the event dispatch thread. The frame
 * counters are updated by the renderer ({@link Canvas3D#postSwap()}) and read from any thread.
 */
public final class SceneView {
    /**
     * Background colour, 0xRRGGBB (a compile-time constant: tests compare screenshot pixels with
     * it): a middle grey-blue, so a black model shows as dark on it and a white one as light.
     */
    public static final int BACKGROUND_RGB = 0x56616E;
    static final int MAX_CONTACTS = 64;
    static final double NORMAL_LENGTH_M = 0.035;
    /**
     * Height of a drawn friction cone along the contact normal, m: each edge f_i (normal component
     * 1, {@link FrictionCone}) is drawn from the contact point back to p − h·f_i, outside the
     * object, so a cone is h high and μ·h wide in radius, on the scale of the links (~50 mm).
     */
    static final double CONE_HEIGHT_M = 0.02;
    /** Most edges a drawn cone has (a cone of more edges is drawn with this many). */
    static final int MAX_CONE_EDGES = 32;
    /** Colours of the fingers' cones, 0xRRGGBB: the charts' finger colours ({@link TraceCharts#FINGER_RGB}). */
    static final int[] CONE_RGB = TraceCharts.FINGER_RGB;
    private static final BoundingSphere EVERYWHERE = new BoundingSphere(new Point3d(), 1000);

    private final FrameCountingCanvas canvas;
    private final SimpleUniverse universe;
    private final TransformGroup spinTg = writable(new TransformGroup());
    private final TransformGroup palmTg = writable(new TransformGroup());
    private final TransformGroup[][] linkTg = new TransformGroup[3][3];
    private final TransformGroup objectTg = writable(new TransformGroup());
    private final Switch handSwitch = switchNode(), objectSwitch = switchNode(), contactSwitch = switchNode(), markerSwitch = switchNode();
    private final Switch coneSwitch = switchNode();
    private final DoubleBufferedLines cones;
    private final float[] coneCoords = new float[12 * MAX_CONE_EDGES * MAX_CONTACTS];
    private final float[] coneColours = new float[12 * MAX_CONE_EDGES * MAX_CONTACTS];
    private final double[] coneEdges = new double[3 * MAX_CONE_EDGES];
    private double coneMu = FrictionCone.DEFAULT_MU;
    private int coneEdgeCount = FrictionCone.DEFAULT_EDGES;
    private final TransformGroup[] contactTg = new TransformGroup[MAX_CONTACTS];
    private final DoubleBufferedLines normals;
    private final float[] normalCoords = new float[6 * MAX_CONTACTS];
    private final TransformGroup targetTg = writable(new TransformGroup()), closestTg = writable(new TransformGroup());
    private final SpinBehavior spin = new SpinBehavior();
    private final OrbitBehavior orbit;
    private final Transform3D scratch = new Transform3D();
    private final Vector3d scratchV = new Vector3d();
    private final double[] m16 = new double[16];
    private BranchGroup objectBranch;
    private double objectScale = 1;
    private boolean showContacts = true, showNormals = true, showCones;
    private Pose lastPose;
    private final View view3d;
    private final int handTriangles;

    /**
     * Builds the view with the hand's meshes (palm in {P}, links 1–3 each in {kj}).
     *
     * @param palm  palm mesh and colour
     * @param links link 1, 2, 3 meshes and colours
     */
    public SceneView(MeshSource.Model palm, MeshSource.Model[] links) {
        handTriangles = palm.mesh().triangleCount()
            + 3 * (links[0].mesh().triangleCount() + links[1].mesh().triangleCount() + links[2].mesh().triangleCount());
        GraphicsConfiguration gc = SimpleUniverse.getPreferredConfiguration();
        canvas = new FrameCountingCanvas(gc);
        universe = new SimpleUniverse(canvas);
        View view = universe.getViewer().getView();
        view3d = view;
        view.setFrontClipDistance(0.005);
        view.setBackClipDistance(20);
        view.setFieldOfView(Math.toRadians(FIELD_OF_VIEW_DEG));

        BranchGroup root = new BranchGroup();
        Background bg = new Background(new Color3f(((BACKGROUND_RGB >> 16) & 255) / 255f,
            ((BACKGROUND_RGB >> 8) & 255) / 255f, (BACKGROUND_RGB & 255) / 255f));
        bg.setApplicationBounds(EVERYWHERE);
        root.addChild(bg);
        // ambient, a key light from above, a fill from below and a headlight that moves with the
        // camera: every side the camera sees is lit, and specular highlights show a black model's shape
        AmbientLight ambient = new AmbientLight(new Color3f(0.34f, 0.34f, 0.36f));
        ambient.setInfluencingBounds(EVERYWHERE);
        root.addChild(ambient);
        DirectionalLight key = new DirectionalLight(new Color3f(0.70f, 0.70f, 0.67f), new Vector3f(-0.5f, -0.8f, -0.6f));
        key.setInfluencingBounds(EVERYWHERE);
        root.addChild(key);
        DirectionalLight fill = new DirectionalLight(new Color3f(0.25f, 0.27f, 0.30f), new Vector3f(0.7f, 0.2f, 0.6f));
        fill.setInfluencingBounds(EVERYWHERE);
        root.addChild(fill);
        org.jogamp.java3d.utils.universe.PlatformGeometry head = new org.jogamp.java3d.utils.universe.PlatformGeometry();
        DirectionalLight headlight = new DirectionalLight(new Color3f(0.40f, 0.40f, 0.40f), new Vector3f(0, 0, -1));
        headlight.setInfluencingBounds(EVERYWHERE);
        head.addChild(headlight);
        universe.getViewingPlatform().setPlatformGeometry(head);

        TransformGroup worldToVworld = new TransformGroup();
        Transform3D rx = new Transform3D();
        rx.rotX(-Math.PI / 2);
        worldToVworld.setTransform(rx);
        root.addChild(worldToVworld);
        worldToVworld.addChild(spinTg);
        spin.setSchedulingBounds(EVERYWHERE);
        spin.setEnable(false);
        root.addChild(spin);

        // the hand
        palmTg.setCapability(TransformGroup.ALLOW_TRANSFORM_READ);
        spinTg.addChild(handSwitch);
        handSwitch.addChild(palmTg);
        handSwitch.setWhichChild(Switch.CHILD_ALL);
        palmTg.addChild(shape(palm.mesh(), appearance(palm.colour(), new float[] {0.25f, 0.25f, 0.28f})));
        palmTg.addChild(floorGrid());
        TriangleArray[] linkGeometry = new TriangleArray[3];
        Appearance[] linkLook = new Appearance[3];
        for (int j = 0; j < 3; j++) {
            linkGeometry[j] = geometry(links[j].mesh(), 0.5);
            linkLook[j] = appearance(links[j].colour(), new float[] {0.55f, 0.57f, 0.6f});
        }
        for (int k = 0; k < 3; k++) {
            for (int j = 0; j < 3; j++) {
                linkTg[k][j] = writable(new TransformGroup());
                linkTg[k][j].addChild(new Shape3D(linkGeometry[j], linkLook[j]));
                handSwitch.addChild(linkTg[k][j]);
            }
        }

        // the object
        objectTg.setCapability(TransformGroup.ALLOW_TRANSFORM_READ);
        objectTg.setCapability(TransformGroup.ALLOW_CHILDREN_EXTEND);
        objectTg.setCapability(TransformGroup.ALLOW_CHILDREN_WRITE);
        objectSwitch.addChild(objectTg);
        objectSwitch.setWhichChild(Switch.CHILD_ALL);
        spinTg.addChild(objectSwitch);

        // contacts: spheres and normals
        // contact points lie inside both bodies (the centre of the intersection patch): drawn
        // in the transparent pass, after the opaque scene, without the depth test, so they show
        Appearance dot = appearance(new float[] {1f, 0.85f, 0.1f}, null);
        dot.getMaterial().setEmissiveColor(0.6f, 0.5f, 0f);
        onTop(dot);
        for (int i = 0; i < MAX_CONTACTS; i++) {
            contactTg[i] = writable(new TransformGroup());
            contactTg[i].addChild(new Sphere(0.0045f, Sphere.GENERATE_NORMALS, 12, dot));
            contactSwitch.addChild(contactTg[i]);
        }
        Appearance lineLook = new Appearance();
        lineLook.setColoringAttributes(new ColoringAttributes(new Color3f(0.2f, 1f, 0.4f), ColoringAttributes.FASTEST));
        lineLook.setLineAttributes(new LineAttributes(3f, LineAttributes.PATTERN_SOLID, true));
        onTop(lineLook);
        normals = new DoubleBufferedLines(2 * MAX_CONTACTS, GeometryArray.COORDINATES, lineLook);
        contactSwitch.addChild(normals.shape());
        contactSwitch.setWhichChild(Switch.CHILD_MASK);
        contactSwitch.setChildMask(new BitSet());
        spinTg.addChild(contactSwitch);

        // friction cones: per-vertex colours (the finger's), over the scene like the normals
        Appearance coneLook = new Appearance();
        coneLook.setLineAttributes(new LineAttributes(2f, LineAttributes.PATTERN_SOLID, true));
        onTop(coneLook);
        cones = new DoubleBufferedLines(4 * MAX_CONE_EDGES * MAX_CONTACTS, GeometryArray.COORDINATES | GeometryArray.COLOR_3, coneLook);
        coneSwitch.addChild(cones.shape());
        coneSwitch.setWhichChild(Switch.CHILD_NONE);
        spinTg.addChild(coneSwitch);

        // inverse-kinematics markers
        Appearance targetLook = appearance(new float[] {0.9f, 0.2f, 0.9f}, null);
        targetLook.getMaterial().setEmissiveColor(0.4f, 0f, 0.4f);
        Appearance closestLook = appearance(new float[] {0.2f, 0.8f, 1f}, null);
        closestLook.getMaterial().setEmissiveColor(0f, 0.3f, 0.4f);
        targetTg.addChild(new Sphere(0.005f, Sphere.GENERATE_NORMALS, 14, targetLook));
        closestTg.addChild(new Sphere(0.004f, Sphere.GENERATE_NORMALS, 14, closestLook));
        markerSwitch.addChild(targetTg);
        markerSwitch.addChild(closestTg);
        markerSwitch.setWhichChild(Switch.CHILD_MASK);
        markerSwitch.setChildMask(new BitSet());
        spinTg.addChild(markerSwitch);

        root.compile();
        universe.addBranchGraph(root);

        orbit = new OrbitBehavior(canvas, OrbitBehavior.REVERSE_ROTATE | OrbitBehavior.REVERSE_TRANSLATE);
        orbit.setSchedulingBounds(EVERYWHERE);
        orbit.setZoomFactor(0.15);
        orbit.setTransFactors(0.15, 0.15);
        universe.getViewingPlatform().setViewPlatformBehavior(orbit);
        lookAt(RigidTransform.IDENTITY);
    }

    /** Triangles of the palm and the nine links. */
    public int handTriangles() { return handTriangles; }

    /** The heavyweight canvas to put in the window. */
    public Canvas3D canvas() { return canvas; }

    /**
     * Points the camera at the hand and makes that the orbit's home: from the palm's +x side
     * and above, so finger 3's closing plane (the paper's experiment, Fig. 6) is seen nearly
     * face-on, with fingers 1 and 2 beside it.
     */
    public void lookAt(RigidTransform worldFromPalm) {
        view3d.setFrontClipDistance(0.005);
        view3d.setBackClipDistance(20);
        place(worldFromPalm.apply(HOME_EYE_IN_PALM), worldFromPalm.apply(HOME_AT_IN_PALM), new double[] {0, 0, 1});
    }

    /** The home view in the palm frame, m: the eye, and the point it looks at. */
    private static final double[] HOME_EYE_IN_PALM = {0.42, 0.16, 0.22}, HOME_AT_IN_PALM = {0, 0.01, 0.10};

    /**
     * Shows a pose: palm, links, a free object (when the pose has one: at its pose, with the
     * scale it was given), contacts and markers. Event dispatch thread only.
     */
    public void show(Pose p) {
        lastPose = p;
        set(palmTg, p.worldFromPalm(), 0, 1);
        if (p.worldFromObject() != null) set(objectTg, p.worldFromObject(), 0, objectScale);
        for (int k = 0; k < 3; k++) {
            for (int j = 0; j < 3; j++) set(linkTg[k][j], p.framesWorld()[k], 12 * (j + 1), 1);
        }
        int n = Math.min(MAX_CONTACTS, p.contactCount());
        BitSet mask = new BitSet(MAX_CONTACTS + 1);
        double[] pts = p.contactPoints(), nrm = p.contactNormals();
        for (int i = 0; i < n; i++) {
            translate(contactTg[i], pts, 3 * i);
            mask.set(i);
            for (int c = 0; c < 3; c++) {
                normalCoords[6 * i + c] = (float) pts[3 * i + c];
                normalCoords[6 * i + 3 + c] = (float) (pts[3 * i + c] + NORMAL_LENGTH_M * nrm[3 * i + c]);
            }
        }
        if (n > 0) {
            LineArray g = normals.spare();
            g.setCoordinates(0, normalCoords, 0, 2 * n);
            g.setValidVertexCount(2 * n);
            normals.swap();
            if (showNormals) mask.set(MAX_CONTACTS);
        }
        contactSwitch.setChildMask(showContacts ? mask : new BitSet());
        int lines = showCones && n > 0 ? coneLines(p, n) : 0;
        coneSwitch.setWhichChild(showCones && lines > 0 ? Switch.CHILD_ALL : Switch.CHILD_NONE);
        BitSet markers = new BitSet(2);
        if (p.target() != null) { translate(targetTg, p.target(), 0); markers.set(0); }
        if (p.closest() != null) { translate(closestTg, p.closest(), 0); markers.set(1); }
        markerSwitch.setChildMask(markers);
    }

    /**
     * Writes the friction cones of the first {@code n} contacts of {@code p} into the cone lines:
     * per contact m edges from the contact point to p − h·f_i and the m segments of the rim
     * through their ends (h = {@link #CONE_HEIGHT_M}; f_i the edges of {@link FrictionCone} about
     * the normal into the object, the opposite of the pose's outward normal), in the colour of
     * the contact's finger (a contact without a normal direction gets none). Returns the number
     * of line segments. No allocation.
     */
    private int coneLines(Pose p, int n) {
        int m = Math.min(coneEdgeCount, MAX_CONE_EDGES);
        double[] pts = p.contactPoints(), nrm = p.contactNormals();
        int[] fingers = p.contactFingers();
        int v = 0;
        for (int i = 0; i < n; i++) {
            double nx = nrm[3 * i], ny = nrm[3 * i + 1], nz = nrm[3 * i + 2], len2 = nx * nx + ny * ny + nz * nz;
            if (!(len2 > 0) || !Double.isFinite(len2)) continue;    // no direction: no cone (never an exception on the EDT)
            FrictionCone.edges(-nx, -ny, -nz, coneMu, m, coneEdges, 0);
            int rgb = CONE_RGB[Math.max(0, Math.min(2, fingers[i] - 1))];
            float r = ((rgb >> 16) & 255) / 255f, g = ((rgb >> 8) & 255) / 255f, b = (rgb & 255) / 255f;
            for (int e = 0; e < m; e++) {
                int e2 = (e + 1) % m;
                for (int c = 0; c < 3; c++) {
                    double apex = pts[3 * i + c];
                    double rim = apex - CONE_HEIGHT_M * coneEdges[3 * e + c], rim2 = apex - CONE_HEIGHT_M * coneEdges[3 * e2 + c];
                    coneCoords[3 * v + c] = (float) apex;            // edge: apex to rim
                    coneCoords[3 * v + 3 + c] = (float) rim;
                    coneCoords[3 * v + 6 + c] = (float) rim;         // rim segment
                    coneCoords[3 * v + 9 + c] = (float) rim2;
                }
                for (int k = 0; k < 4; k++) {
                    coneColours[3 * (v + k)] = r;
                    coneColours[3 * (v + k) + 1] = g;
                    coneColours[3 * (v + k) + 2] = b;
                }
                v += 4;
            }
        }
        if (v == 0) return 0;
        LineArray g = cones.spare();
        g.setCoordinates(0, coneCoords, 0, v);
        g.setColors(0, coneColours, 0, v);
        g.setValidVertexCount(v);
        cones.swap();
        return v / 2;
    }

    /**
     * The friction the cones are drawn with: Coulomb μ and the edges m of the linearised cone
     * (the scenario's {@code object.friction} and cone edges; at most {@link #MAX_CONE_EDGES}
     * are drawn). From the next pose shown. Event dispatch thread only.
     */
    public void setFriction(double mu, int edges) {
        coneMu = FrictionCone.checkMu(mu);
        coneEdgeCount = FrictionCone.checkEdges(edges);
    }

    /**
     * Where a world point is drawn in the canvas, pixels from its top-left corner {x, y} (for
     * tests: where a contact is on a screenshot). Uses the last rendered view. Event dispatch thread.
     */
    public double[] pixelOf(double[] world) {
        Transform3D toPlate = new Transform3D();
        canvas.getVworldToImagePlate(toPlate);
        Point3d v = new Point3d(world[0], world[2], -world[1]);   // world (x, y, z) -> vworld (x, z, -y); the spin is off
        toPlate.transform(v);
        org.jogamp.vecmath.Point2d px = new org.jogamp.vecmath.Point2d();
        canvas.getPixelLocationFromImagePlate(v, px);
        return new double[] {px.x, px.y};
    }

    /**
     * Replaces the object (null: none). Event dispatch thread only.
     *
     * @param model           the mesh in the object's own frame
     * @param worldFromObject placement
     * @param scale           uniform scale applied in the object's frame before placing it
     */
    public void setObject(MeshSource.Model model, RigidTransform worldFromObject, double scale) {
        if (objectBranch != null) {
            objectBranch.detach();
            objectBranch = null;
        }
        if (model == null) return;
        BranchGroup b = new BranchGroup();
        b.setCapability(BranchGroup.ALLOW_DETACH);
        b.addChild(shape(model.mesh(), appearance(model.colour(), new float[] {0.85f, 0.25f, 0.2f})));
        b.compile();
        placeObject(worldFromObject, scale);
        objectTg.addChild(b);
        objectBranch = b;
    }

    /** Moves the object. Event dispatch thread only. */
    public void placeObject(RigidTransform worldFromObject, double scale) {
        objectScale = scale;
        set(objectTg, worldFromObject.toArray(), 0, scale);
    }

    /**
     * The object's transform as the scene graph holds it (its {@code TransformGroup}: world ←
     * object, the rotation times the mesh's scale), 16 row-major values, for checks that the view
     * shows where the model has the object. Event dispatch thread.
     */
    public double[] objectTransform() { return transform(objectTg); }

    /** The palm's transform as the scene graph holds it (world ← palm), 16 row-major values. Event dispatch thread. */
    public double[] palmTransform() { return transform(palmTg); }

    private static double[] transform(TransformGroup tg) {
        Transform3D t = new Transform3D();
        tg.getTransform(t);
        double[] m = new double[16];
        t.get(m);
        return m;
    }

    /** What {@link #setVisible} can hide. */
    public enum Part { HAND, OBJECT, CONTACTS, NORMALS, CONES }

    /**
     * Shows or hides a part of the scene (contacts and normals from the next pose shown; the
     * friction cones, hidden at first, at once). Event dispatch thread only.
     */
    public void setVisible(Part part, boolean on) {
        switch (part) {
            case CONES:
                showCones = on;
                if (!on) coneSwitch.setWhichChild(Switch.CHILD_NONE);
                else if (lastPose != null) show(lastPose);
                break;
            case HAND: handSwitch.setWhichChild(on ? Switch.CHILD_ALL : Switch.CHILD_NONE); break;
            case OBJECT: objectSwitch.setWhichChild(on ? Switch.CHILD_ALL : Switch.CHILD_NONE); break;
            case NORMALS:
                showNormals = on;
                if (!on) {
                    BitSet m = (BitSet) contactSwitch.getChildMask().clone();
                    m.clear(MAX_CONTACTS);
                    contactSwitch.setChildMask(m);
                }
                break;
            default:
                showContacts = on;
                if (!on) contactSwitch.setChildMask(new BitSet());
        }
    }

    // ------------------------------------------------------------------ camera
    /** Vertical field of view, degrees. */
    static final double FIELD_OF_VIEW_DEG = 40;

    /**
     * Camera positions: the home view, one that fits the whole scene, and three along the palm's
     * axes (each framing the scene). {@link #key()} is the window's shortcut.
     */
    public enum Camera {
        HOME("home", "Home view", "H"), FIT("fit", "Fit to the scene", "F"), FRONT("front", "Front (palm x)", "1"),
        TOP("top", "Top (palm z, looking at the palm)", "2"), SIDE("side", "Side (palm y)", "3");

        private final String id, label, key;

        Camera(String id, String label, String key) {
            this.id = id;
            this.label = label;
            this.key = key;
        }

        /** Name in scripts and menus: home, fit, front, top, side. */
        public String id() { return id; }
        public String label() { return label; }
        public String key() { return key; }

        /** The camera named {@code id}, or null. */
        public static Camera of(String id) {
            for (Camera c : values()) if (c.id.equalsIgnoreCase(id)) return c;
            return null;
        }
    }

    /** Radius of a sphere round the hand's palm and open fingers, m (palm frame, centre {@link #HAND_CENTRE}). */
    static final double HAND_RADIUS_M = 0.17;
    static final double[] HAND_CENTRE = {0, 0, 0.10};

    /**
     * The scene's bounding sphere in the world {cx, cy, cz, r}: the hand's and the object's
     * (its mesh at its placement), m.
     */
    public static double[] sceneSphere(org.handsim.scenario.Scenario s, MeshSource.Model object) {
        double[] hc = s.worldFromPalm().apply(HAND_CENTRE);
        double[] a = {hc[0], hc[1], hc[2], HAND_RADIUS_M};
        if (object == null || s.object() == null) return a;
        double[] os = org.handsim.model.SceneGeometry.boundingSphere(object.mesh());
        double k = s.object().meshScale();
        double[] oc = s.object().worldFromObject().apply(new double[] {k * os[0], k * os[1], k * os[2]});
        double[] b = {oc[0], oc[1], oc[2], k * os[3]};
        // the smallest sphere round both
        double dx = b[0] - a[0], dy = b[1] - a[1], dz = b[2] - a[2], d = Math.sqrt(dx * dx + dy * dy + dz * dz);
        if (d + b[3] <= a[3]) return a;
        if (d + a[3] <= b[3]) return b;
        double r = 0.5 * (d + a[3] + b[3]);
        double t = (r - a[3]) / d;
        return new double[] {a[0] + t * dx, a[1] + t * dy, a[2] + t * dz, r};
    }

    /**
     * Moves the camera to {@code c}, framing the scene of {@code s} (and its object's mesh, if
     * loaded) so that all of it is in view; the orbit turns about the scene's centre and Home
     * view returns to the home position. Event dispatch thread.
     */
    public void camera(Camera c, org.handsim.scenario.Scenario s, MeshSource.Model object) {
        if (c == Camera.HOME) {
            lookAt(s.worldFromPalm());
            return;
        }
        double[] sphere = sceneSphere(s, object);
        org.handsim.math.RigidTransform wp = s.worldFromPalm();
        double[] dir, up;
        switch (c) {
            case FRONT: dir = wp.axis(0); up = wp.axis(2); break;
            case TOP: dir = wp.axis(2); up = wp.axis(0); break;
            case SIDE: dir = wp.axis(1); up = wp.axis(2); break;
            default: {
                // the home view's direction
                double[] eye = wp.apply(HOME_EYE_IN_PALM), at = wp.apply(HOME_AT_IN_PALM);
                dir = new double[] {eye[0] - at[0], eye[1] - at[1], eye[2] - at[2]};
                up = wp.axis(2);
            }
        }
        double n = Math.sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
        double aspect = canvas.getWidth() > 0 && canvas.getHeight() > 0 ? canvas.getWidth() / (double) canvas.getHeight() : 1;
        // the field of view is horizontal in Java3D: fit the sphere in the narrower of the two directions
        double half = Math.toRadians(FIELD_OF_VIEW_DEG) / 2;
        double halfVertical = Math.atan(Math.tan(half) / Math.max(aspect, 1e-3));
        double distance = 1.08 * sphere[3] / Math.sin(Math.min(half, halfVertical));
        double[] eye = {sphere[0] + distance * dir[0] / n, sphere[1] + distance * dir[1] / n, sphere[2] + distance * dir[2] / n};
        view3d.setBackClipDistance(Math.max(20, 3 * distance));
        view3d.setFrontClipDistance(Math.max(0.005, Math.min(0.05, distance / 200)));
        place(eye, sphere, up);
    }

    /** Puts the camera at {@code eye} (world) looking at {@code at} with {@code up}; sets the orbit's centre and home there. */
    private void place(double[] eye, double[] at, double[] up) {
        // world (x, y, z) -> vworld (x, z, -y)
        Point3d center = new Point3d(at[0], at[2], -at[1]);
        Point3d eyeV = new Point3d(eye[0], eye[2], -eye[1]);
        Transform3D t = new Transform3D();
        t.lookAt(eyeV, center, new Vector3d(up[0], up[2], -up[1]));
        t.invert();
        orbit.setRotationCenter(center);
        // through the orbit behaviour, which keeps its own copy of the camera (a transform set
        // directly would be undone by the next mouse drag)
        orbit.setHomeTransform(t);
        orbit.goHome();
    }

    /** The camera's position in the world, m (for tests). */
    public double[] eyeWorld() {
        Transform3D t = new Transform3D();
        universe.getViewingPlatform().getViewPlatformTransform().getTransform(t);
        Vector3d v = new Vector3d();
        t.get(v);
        return new double[] {v.x, -v.z, v.y};
    }

    /** Frames rendered so far (counted after each buffer swap). */
    public long framesRendered() { return canvas.frames.get(); }

    /** Milliseconds from the JVM's start to the first rendered frame, or -1 before it. */
    public long firstFrameMillisSinceJvmStart() { return canvas.firstFrameMs; }

    /** Wall-clock time of the first rendered frame (ms since 1970), or -1 before it. */
    public long firstFrameEpochMillis() { return canvas.firstFrameEpochMs; }

    /**
     * Renders continuously for {@code seconds}, turning the scene slowly about the vertical
     * axis so every frame differs, and returns the frames per second actually swapped. Blocks:
     * never call it on the event dispatch thread.
     */
    public double measureFps(double seconds) throws InterruptedException {
        spin.setEnable(true);
        Thread.sleep(300); // let the pipeline fill
        long f0 = canvas.frames.get(), t0 = System.nanoTime();
        Thread.sleep((long) (seconds * 1000));
        long f1 = canvas.frames.get(), t1 = System.nanoTime();
        spin.setEnable(false);
        spin.reset();
        return (f1 - f0) / ((t1 - t0) / 1e9);
    }

    /** Stops Java3D's threads for this view. */
    public void dispose() {
        universe.cleanup();
    }

    // ------------------------------------------------------------------ building blocks
    private void set(TransformGroup tg, double[] m, int off, double scale) {
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) m16[4 * r + c] = m[off + 4 * r + c] * scale;
            m16[4 * r + 3] = m[off + 4 * r + 3];
        }
        m16[12] = 0; m16[13] = 0; m16[14] = 0; m16[15] = 1;
        scratch.set(m16);
        tg.setTransform(scratch);
    }

    /** Places {@code tg} at the point {@code p[off..off+2]}. */
    private void translate(TransformGroup tg, double[] p, int off) {
        scratch.setIdentity();
        scratchV.set(p[off], p[off + 1], p[off + 2]);
        scratch.setTranslation(scratchV);
        tg.setTransform(scratch);
    }

    /** Draws with this appearance after the opaque scene and over it (markers inside bodies). */
    private static void onTop(Appearance a) {
        a.setTransparencyAttributes(new TransparencyAttributes(TransparencyAttributes.BLENDED, 0.05f));
        RenderingAttributes r = new RenderingAttributes();
        r.setDepthBufferEnable(false);
        r.setDepthBufferWriteEnable(false);
        a.setRenderingAttributes(r);
    }

    private static TransformGroup writable(TransformGroup tg) {
        tg.setCapability(TransformGroup.ALLOW_TRANSFORM_WRITE);
        return tg;
    }

    private static Switch switchNode() {
        Switch s = new Switch();
        s.setCapability(Switch.ALLOW_SWITCH_WRITE);
        return s;
    }

    static Appearance appearance(float[] rgb, float[] fallback) {
        float[] c = rgb != null ? rgb : fallback;
        Appearance a = new Appearance();
        Material m = new Material();
        m.setDiffuseColor(c[0], c[1], c[2]);
        m.setAmbientColor(c[0], c[1], c[2]);
        m.setSpecularColor(0.35f, 0.35f, 0.35f);
        m.setShininess(24f);
        m.setLightingEnable(true);
        m.setCapability(Material.ALLOW_COMPONENT_WRITE);
        a.setMaterial(m);
        a.setPolygonAttributes(new PolygonAttributes(PolygonAttributes.POLYGON_FILL, PolygonAttributes.CULL_BACK, 0));
        return a;
    }

    static Shape3D shape(TriangleMesh mesh, Appearance look) {
        return new Shape3D(geometry(mesh, 0.5), look);
    }

    /**
     * The mesh as a non-indexed {@link TriangleArray} with per-corner normals: the area-weighted
     * mean of the normals of the triangles round the vertex that lie within {@code creaseAngle}
     * radians of the corner's own triangle (VRML's creaseAngle rule), so curved surfaces look
     * smooth and edges stay sharp.
     */
    static TriangleArray geometry(TriangleMesh mesh, double creaseAngle) {
        int nt = mesh.triangleCount(), nv = mesh.vertexCount();
        double[] v = mesh.vertices(), fn = mesh.normals(), area = mesh.areas();
        int[] tri = mesh.triangles();
        int[] start = new int[nv + 1];
        for (int i : tri) start[i + 1]++;
        for (int i = 0; i < nv; i++) start[i + 1] += start[i];
        int[] fill = start.clone(), around = new int[tri.length];
        for (int i = 0; i < tri.length; i++) around[fill[tri[i]]++] = i / 3;
        double cosCrease = Math.cos(creaseAngle);
        float[] coords = new float[9 * nt], normal = new float[9 * nt];
        for (int t = 0; t < nt; t++) {
            for (int c = 0; c < 3; c++) {
                int vi = tri[3 * t + c], o = 9 * t + 3 * c;
                coords[o] = (float) v[3 * vi];
                coords[o + 1] = (float) v[3 * vi + 1];
                coords[o + 2] = (float) v[3 * vi + 2];
                double sx = 0, sy = 0, sz = 0;
                for (int a = start[vi]; a < start[vi + 1]; a++) {
                    int u = around[a];
                    double dot = fn[3 * t] * fn[3 * u] + fn[3 * t + 1] * fn[3 * u + 1] + fn[3 * t + 2] * fn[3 * u + 2];
                    if (u == t || dot >= cosCrease) {
                        sx += area[u] * fn[3 * u];
                        sy += area[u] * fn[3 * u + 1];
                        sz += area[u] * fn[3 * u + 2];
                    }
                }
                double len = Math.sqrt(sx * sx + sy * sy + sz * sz);
                if (len == 0) { sx = fn[3 * t]; sy = fn[3 * t + 1]; sz = fn[3 * t + 2]; len = 1; }
                normal[o] = (float) (sx / len);
                normal[o + 1] = (float) (sy / len);
                normal[o + 2] = (float) (sz / len);
            }
        }
        TriangleArray g = new TriangleArray(Math.max(3, 3 * nt), GeometryArray.COORDINATES | GeometryArray.NORMALS);
        if (nt > 0) {
            g.setCoordinates(0, coords);
            g.setNormals(0, normal);
        }
        return g;
    }

    /** A 0.40 m grid of 20 mm squares just under the palm (palm frame z = −1 mm). */
    private static Node floorGrid() {
        int lines = 21;
        double half = 0.20, z = -0.001;
        LineArray g = new LineArray(4 * lines, GeometryArray.COORDINATES);
        int at = 0;
        for (int i = 0; i < lines; i++) {
            double s = -half + i * (2 * half / (lines - 1));
            g.setCoordinate(at++, new Point3d(s, -half, z));
            g.setCoordinate(at++, new Point3d(s, half, z));
            g.setCoordinate(at++, new Point3d(-half, s, z));
            g.setCoordinate(at++, new Point3d(half, s, z));
        }
        Appearance a = new Appearance();
        a.setColoringAttributes(new ColoringAttributes(new Color3f(0.36f, 0.40f, 0.46f), ColoringAttributes.FASTEST));
        return new Shape3D(g, a);
    }

    /** Counts buffer swaps; remembers when the first one happened. */
    private static final class FrameCountingCanvas extends Canvas3D {
        private static final long serialVersionUID = 1L;
        final AtomicLong frames = new AtomicLong();
        volatile long firstFrameMs = -1, firstFrameEpochMs = -1;

        FrameCountingCanvas(GraphicsConfiguration gc) {
            super(gc);
        }

        @Override
        public void postSwap() {
            if (firstFrameMs < 0) {
                firstFrameEpochMs = System.currentTimeMillis();
                firstFrameMs = firstFrameEpochMs - ManagementFactory.getRuntimeMXBean().getStartTime();
            }
            frames.incrementAndGet();
        }
    }

    /** Turns the scene a little every frame while enabled (the frame-rate measurement). */
    private final class SpinBehavior extends Behavior {
        private final WakeupOnElapsedFrames everyFrame = new WakeupOnElapsedFrames(0);
        private final Transform3D t = new Transform3D();
        private double angle;

        @Override
        public void initialize() {
            wakeupOn(everyFrame);
        }

        @Override
        public void processStimulus(Iterator<org.jogamp.java3d.WakeupCriterion> criteria) {
            angle += 0.01;
            t.rotZ(angle);
            spinTg.setTransform(t);
            wakeupOn(everyFrame);
        }

        void reset() {
            angle = 0;
            t.setIdentity();
            spinTg.setTransform(t);
        }
    }
}
