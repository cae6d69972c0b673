package org.handsim.vrml;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.zip.GZIPOutputStream;
import org.handsim.mesh.TessellationWalk;
import org.handsim.mesh.TriangleMesh;
import org.jogamp.java3d.BranchGroup;
import org.jogamp.java3d.Link;
import org.jogamp.java3d.Material;
import org.jogamp.java3d.PolygonAttributes;
import org.jogamp.java3d.Shape3D;
import org.jogamp.java3d.SharedGroup;
import org.jogamp.java3d.Switch;
import org.jogamp.java3d.Transform3D;
import org.jogamp.java3d.TransformGroup;
import org.jogamp.java3d.TransparencyAttributes;
import org.jogamp.vecmath.Color3f;
import org.jogamp.vecmath.Point3d;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** Loader features on small hand-written scenes with hand-worked expectations. */
class VrmlLoaderTest {
    private Path dir;

    @BeforeEach
    void makeDir() throws IOException {
        dir = VrmlTesting.tempDir();
    }

    @AfterEach
    void removeDir() throws IOException {
        VrmlTesting.deleteTree(dir);
    }

    private static final String BOX = "Shape { geometry Box { } }";

    // ------------------------------------------------------------------ DEF/USE

    @Test
    void useSharesTheNodeThroughASharedGroup() {
        VrmlScene s = VrmlTesting.load("DEF Part Transform { children " + BOX + " }\n"
            + "Transform { translation 3 0 0 children USE Part }\n");
        BranchGroup bg = s.getSceneGroup();
        Link a = (Link) bg.getChild(0);
        Link b = (Link) ((TransformGroup) bg.getChild(1)).getChild(0);
        SharedGroup sg = a.getSharedGroup();
        assertSame(sg, b.getSharedGroup(), "both uses point at one SharedGroup: shared, not copied");
        assertSame(sg.getChild(0), s.getNamedObjects().get("Part"));
        assertEquals("Part", ((TransformGroup) sg.getChild(0)).getName());
        TessellationWalk.Result r = VrmlTesting.walk(s);
        assertEquals(2, r.shapes);
        assertEquals(24, r.merged().triangleCount());
        assertEquals(4.0, r.merged().bounds()[1][0], 1e-12, "the second use is translated by 3");
    }

    @Test
    void useOfGeometryAndAppearanceSharesJava3dComponents() {
        VrmlScene s = VrmlTesting.load("Shape { appearance DEF Red Appearance { material Material { diffuseColor 1 0 0 } }"
            + " geometry DEF G Sphere { } }\n"
            + "Transform { translation 3 0 0 children Shape { appearance USE Red geometry USE G } }\n");
        Shape3D a = (Shape3D) s.getSceneGroup().getChild(0);
        Shape3D b = (Shape3D) ((TransformGroup) s.getSceneGroup().getChild(1)).getChild(0);
        assertSame(a.getGeometry(), b.getGeometry());
        assertSame(a.getAppearance(), b.getAppearance());
        assertSame(a.getGeometry(), s.getNamedObjects().get("G"));
        Color3f c = new Color3f();
        a.getAppearance().getMaterial().getDiffuseColor(c);
        assertEquals(new Color3f(1, 0, 0), c);
    }

    @Test
    void solidFalseShowsBackFacesAndPrimitivesStaySolid() {
        VrmlScene s = VrmlTesting.load("Shape { geometry DEF G IndexedFaceSet { solid FALSE coord Coordinate { point [ 0 0 0, 1 0 0, 0 1 0 ] }"
            + " coordIndex [ 0 1 2 ] } }\nShape { geometry USE G }\n" + BOX + "\n");
        Shape3D open = (Shape3D) s.getSceneGroup().getChild(0);
        Shape3D reused = (Shape3D) s.getSceneGroup().getChild(1);
        Shape3D box = (Shape3D) s.getSceneGroup().getChild(2);
        assertEquals(PolygonAttributes.CULL_NONE, open.getAppearance().getPolygonAttributes().getCullFace());
        assertSame(open.getAppearance(), reused.getAppearance(), "a USE of the geometry is two-sided too");
        assertNull(box.getAppearance().getPolygonAttributes(), "Box: Java3D's default back-face culling");
    }

    // ------------------------------------------------------------------ PROTO

    @Test
    void protoInstancesBindFieldsWithIsAndUseDefaults() {
        VrmlScene s = VrmlTesting.load("PROTO Block [ field SFVec3f size 1 1 1  exposedField SFColor color 0 1 0  field SFFloat alpha 0 ] {\n"
            + "  Shape { appearance Appearance { material Material { diffuseColor IS color transparency IS alpha } }\n"
            + "          geometry Box { size IS size } }\n"
            + "}\n"
            + "DEF Big Block { size 2 3 4 color 1 0 0 alpha 0.5 }\n"
            + "Transform { translation 10 0 0 children Block { } }\n");
        List<TriangleMesh> parts = new TessellationWalk().grouping(TessellationWalk.Grouping.SHAPES).run(s.getSceneGroup()).meshes();
        assertEquals(2, parts.size());
        assertEquals(24.0, parts.get(0).signedVolume(), 1e-9);
        assertEquals(1.0, parts.get(1).signedVolume(), 1e-9);
        Shape3D big = (Shape3D) s.getNamedObjects().get("Big");
        Material m = big.getAppearance().getMaterial();
        Color3f c = new Color3f();
        m.getDiffuseColor(c);
        assertEquals(new Color3f(1, 0, 0), c);
        TransparencyAttributes ta = big.getAppearance().getTransparencyAttributes();
        assertEquals(0.5f, ta.getTransparency());
    }

    @Test
    void nestedProtosPassValuesThrough() {
        TriangleMesh m = VrmlTesting.mesh("PROTO Inner [ field SFFloat r 1 ] { Shape { geometry Sphere { radius IS r } } }\n"
            + "PROTO Outer [ field SFFloat radius 1  field MFNode extra [ ] ] {\n"
            + "  Group { children [ Inner { r IS radius } Group { children IS extra } ] }\n"
            + "}\n"
            + "Outer { radius 2 extra [ Shape { geometry Box { size 10 10 10 } } ] }\n");
        double[][] b = m.bounds();
        assertEquals(-5, b[0][0], 1e-9, "the Box passed in through MFNode IS");
        assertTrue(m.triangleCount() > 12, "the Sphere of radius 2 is there too");
    }

    @Test
    void protoUsedAsMaterialAndPrototypeTypeIsItsFirstNode() {
        VrmlScene s = VrmlTesting.load("PROTO Gold [ ] { Material { diffuseColor 1 0.8 0 } Group { } }\n"
            + "Shape { appearance Appearance { material Gold { } } geometry Box { } }\n");
        Color3f c = new Color3f();
        ((Shape3D) s.getSceneGroup().getChild(0)).getAppearance().getMaterial().getDiffuseColor(c);
        assertEquals(new Color3f(1, 0.8f, 0), c);
        assertTrue(s.warnings().isEmpty(), s.warnings().toString());
    }

    @Test
    void externProtoResolvesALocalFileAndSkipsRemoteUrls() throws IOException {
        VrmlTesting.write(dir, "lib/shapes.wrl", VrmlTesting.HEADER
            + "PROTO Other [ ] { Group { } }\n"
            + "PROTO Brick [ field SFVec3f size 1 1 1 ] { Shape { geometry Box { size IS size } } }\n");
        Path main = VrmlTesting.write(dir, "main.wrl", VrmlTesting.HEADER
            + "EXTERNPROTO Brick [ field SFVec3f size ] [ \"urn:web3d:brick\", \"http://example.com/b.wrl\", \"lib/shapes.wrl#Brick\" ]\n"
            + "Brick { size 1 2 3 }\nBrick { }\n");
        VrmlScene s = new VrmlLoader().load(main);
        assertTrue(s.warnings().isEmpty(), s.warnings().toString());
        assertEquals(7.0, TessellationWalk.mesh(s.getSceneGroup()).signedVolume(), 1e-9, "6 + the default 1");
    }

    @Test
    void unresolvedExternProtoIsAWarningAndItsInstancesAreSkipped() {
        VrmlScene s = VrmlTesting.load("EXTERNPROTO Gear [ field SFFloat teeth ] \"http://example.com/gear.wrl\"\n"
            + "Gear { teeth 12 }\n" + BOX + "\n");
        assertEquals(12, TessellationWalk.mesh(s.getSceneGroup()).triangleCount(), "the rest of the scene loads");
        assertTrue(s.warnings().get(0).startsWith("test.wrl:2:1: warning: EXTERNPROTO Gear not resolved"), s.warnings().get(0));
    }

    @Test
    void routesScriptsAndSensorsAreParsedAndIgnored() {
        VrmlScene s = VrmlTesting.load("DEF T TimeSensor { loop TRUE }\n"
            + "DEF S Script { eventIn SFFloat set_f field SFVec3f v 1 2 3 eventOut SFVec3f out url \"javascript: function set_f(f) { out = v; }\" }\n"
            + "DEF X Transform { children " + BOX + " }\n"
            + "ROUTE T.fraction_changed TO S.set_f\nROUTE S.out TO X.set_translation\n");
        assertTrue(s.warnings().isEmpty(), s.warnings().toString());
        assertEquals(12, TessellationWalk.mesh(s.getSceneGroup()).triangleCount());
    }

    // ------------------------------------------------------------------ leniency

    @Test
    void unknownFieldLastFaceWithoutSeparatorAndShortFacesAreWarningsOrAccepted() {
        VrmlScene s = VrmlTesting.load("Viewpoint { centerOfRotation 0 1 0 position 0 0 5 }\n"
            + "Shape { geometry IndexedFaceSet { coord Coordinate { point [ 0 0 0, 1 0 0, 1 1 0, 0 1 0 ] }\n"
            + "  coordIndex [ 0 1 -1 0 1 2 -1 0 2 3 ] } }\n");
        assertEquals(2, s.warnings().size(), s.warnings().toString());
        assertTrue(s.warnings().get(0).startsWith("test.wrl:2:13: warning: unknown field 'centerOfRotation'"), s.warnings().get(0));
        assertTrue(s.warnings().get(1).contains("1 face(s) with fewer than 3 vertices"), s.warnings().get(1));
        TriangleMesh m = TessellationWalk.mesh(s.getSceneGroup());
        assertEquals(2, m.triangleCount(), "the last face without -1 counts");
        assertEquals(1.0, m.area(), 1e-12);
    }

    @Test
    void missingTextureIsAWarning() {
        VrmlScene s = VrmlTesting.load("Shape { appearance Appearance { texture ImageTexture { url \"wood.jpg\" } } geometry Box { } }");
        assertEquals(1, s.warnings().size());
        assertTrue(s.warnings().get(0).contains("texture not available"), s.warnings().get(0));
        assertEquals(12, TessellationWalk.mesh(s.getSceneGroup()).triangleCount());
    }

    // ------------------------------------------------------------------ geometry and transforms

    @Test
    void transformComposesTCRSRSSRinvCinv() {
        // hand-worked: point p = (1, 0, 0) through translation t, centre c, rotation R (90° about z),
        // scale s = (2, 1, 1) with scale orientation SR (90° about z)
        VrmlScene s = VrmlTesting.load("Transform { translation 1 2 3 center 0.5 0 0 rotation 0 0 1 1.5707963267948966"
            + " scale 2 1 1 scaleOrientation 0 0 1 1.5707963267948966 children " + BOX + " }");
        Transform3D t = new Transform3D();
        ((TransformGroup) s.getSceneGroup().getChild(0)).getTransform(t);
        Point3d p = new Point3d(1, 0, 0);
        t.transform(p);
        // C⁻¹: (0.5, 0, 0); SR⁻¹ (−90°): (0, −0.5, 0); S: (0, −0.5, 0) (y unscaled); SR: (0.5, 0, 0);
        // R: (0, 0.5, 0); C: (0.5, 0.5, 0); T: (1.5, 2.5, 3)
        assertEquals(1.5, p.x, 1e-6);
        assertEquals(2.5, p.y, 1e-6);
        assertEquals(3.0, p.z, 1e-6);
        Point3d q = new Point3d(0.5, 1, 0); // along x after SR⁻¹: scaled by 2
        t.transform(q);
        // C⁻¹: (0, 1, 0); SR⁻¹: (1, 0, 0); S: (2, 0, 0); SR: (0, 2, 0); R: (−2, 0, 0); C: (−1.5, 0, 0); T: (−0.5, 2, 3)
        assertEquals(-0.5, q.x, 1e-6);
        assertEquals(2.0, q.y, 1e-6);
        assertEquals(3.0, q.z, 1e-6);
    }

    @Test
    void ccwFalseAndMirrorsKeepOutwardNormals() {
        // a tetrahedron written clockwise (seen from outside) with ccw FALSE
        String tet = "Shape { geometry IndexedFaceSet { ccw FALSE coord Coordinate { point [ 0 0 0, 1 0 0, 0 1 0, 0 0 1 ] }"
            + " coordIndex [ 0 1 2 -1 0 3 1 -1 0 2 3 -1 1 3 2 -1 ] } }";
        TriangleMesh m = VrmlTesting.mesh(tet);
        assertTrue(m.isClosed());
        assertEquals(1.0 / 6, m.signedVolume(), 1e-12);
        TriangleMesh mirrored = VrmlTesting.mesh("Transform { scale -1 1 1 children " + tet + " }");
        assertEquals(1.0 / 6, mirrored.signedVolume(), 1e-12, "a mirror transform reverses the winding back");
        assertEquals(-1.0, mirrored.bounds()[0][0], 1e-12);
    }

    @Test
    void switchAndLodShowOneChild() {
        String three = "Shape { geometry Box { size 1 1 1 } } Shape { geometry Box { size 2 2 2 } } Shape { geometry Box { size 3 3 3 } }";
        VrmlScene s = VrmlTesting.load("Switch { whichChoice 1 choice [ " + three + " ] }");
        assertEquals(8.0, TessellationWalk.mesh(s.getSceneGroup()).signedVolume(), 1e-9);
        assertEquals(1, ((Switch) s.getSceneGroup().getChild(0)).getWhichChild());
        assertEquals(0, TessellationWalk.mesh(VrmlTesting.load("Switch { choice [ " + three + " ] }").getSceneGroup()).triangleCount(),
            "whichChoice -1 (default): nothing");
        assertEquals(1.0, TessellationWalk.mesh(VrmlTesting.load("LOD { level [ " + three + " ] }").getSceneGroup()).signedVolume(), 1e-9);
        assertEquals(27.0, TessellationWalk.mesh(VrmlTesting.load(new VrmlLoader().lodLevel(5), "LOD { level [ " + three + " ] }")
            .getSceneGroup()).signedVolume(), 1e-9, "a level beyond the coarsest is clamped");
    }

    @Test
    void elevationGridAndExtrusion() {
        TriangleMesh grid = VrmlTesting.mesh("Shape { geometry ElevationGrid { xDimension 3 zDimension 3 xSpacing 0.5 zSpacing 0.5"
            + " height [ 0 0 0  0 0 0  0 0 0 ] } }");
        assertEquals(8, grid.triangleCount());
        assertEquals(1.0, grid.area(), 1e-12);
        for (int t = 0; t < 8; t++) assertEquals(1.0, grid.normals()[3 * t + 1], 1e-12, "ccw seen from +y");
        TriangleMesh box = VrmlTesting.mesh("Shape { geometry Extrusion { } }");
        assertTrue(box.isClosed());
        assertEquals(4.0, box.signedVolume(), 1e-9, "default cross-section 2 x 2 along a spine of length 1");
        // a circular cross-section swept along a bent spine: closed, positive volume
        StringBuilder cs = new StringBuilder();
        for (int i = 0; i < 16; i++) cs.append(' ').append(Math.cos(-2 * Math.PI * i / 16)).append(' ').append(Math.sin(-2 * Math.PI * i / 16)).append(',');
        TriangleMesh pipe = VrmlTesting.mesh("Shape { geometry Extrusion { crossSection [" + cs + " 1 0 ] spine [ 0 0 0, 0 2 0, 1 3 0, 3 3 0 ]"
            + " scale [ 0.2 0.2 ] } }");
        assertTrue(pipe.isClosed());
        assertTrue(pipe.signedVolume() > 0, "caps and body consistently oriented");
    }

    @Test
    void namedPartsFollowDefNames() {
        VrmlScene s = VrmlTesting.load("DEF palm Transform { children [ " + BOX
            + " DEF finger Transform { translation 0 2 0 children Shape { geometry Sphere { } } } ] }\n" + BOX + "\n");
        List<TriangleMesh> parts = new TessellationWalk().grouping(TessellationWalk.Grouping.NAMED_PARTS).name("rest")
            .run(s.getSceneGroup()).meshes();
        assertEquals(3, parts.size());
        assertEquals("rest", parts.get(0).name());
        assertEquals("palm", parts.get(1).name());
        assertEquals("finger", parts.get(2).name());
        assertEquals(12, parts.get(1).triangleCount());
    }

    // ------------------------------------------------------------------ Inline sandbox, gzip, inputs

    @Test
    void inlineLoadsLocalFilesOnceAndSharesThem() throws IOException {
        VrmlTesting.write(dir, "parts/wheel.wrl", VrmlTesting.HEADER + "Shape { geometry Cylinder { } }\n");
        VrmlTesting.write(dir, "parts/axle.wrl", VrmlTesting.HEADER + "Inline { url \"wheel.wrl\" }\n"
            + "Transform { translation 0 5 0 children Inline { url [ \"http://example.com/w.wrl\" \"../parts/wheel.wrl\" ] } }\n");
        Path top = VrmlTesting.write(dir, "car.wrl", VrmlTesting.HEADER + "Inline { url \"parts/axle.wrl\" }\n"
            + "Transform { translation 10 0 0 children Inline { url \"parts/axle.wrl\" } }\n");
        VrmlScene s = new VrmlLoader().load(top);
        assertEquals(3, s.files().size(), "each file read once: " + s.files());
        TessellationWalk.Result r = VrmlTesting.walk(s);
        assertEquals(4, r.shapes, "2 axles x 2 wheels");
        assertTrue(s.warnings().isEmpty(), s.warnings().toString());
    }

    private void refused(String url, String reason) throws IOException {
        Path top = VrmlTesting.write(dir, "top.wrl", VrmlTesting.HEADER + "Inline { url \"" + url + "\" }\n");
        VrmlParseException e = assertThrows(VrmlParseException.class, () -> new VrmlLoader().load(top));
        assertTrue(e.getMessage().startsWith(top + ":2:14: Inline "), e.getMessage());
        assertTrue(e.detail().contains(reason), e.getMessage());
    }

    @Test
    void inlineRefusesRemoteAbsoluteAndEscapingUrls() throws IOException {
        Path outside = VrmlTesting.write(dir, "secret.wrl", VrmlTesting.HEADER + BOX);
        Files.createDirectories(dir.resolve("world"));
        Files.move(dir.resolve("secret.wrl"), dir.resolve("world/../secret.wrl"), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        dir = dir.resolve("world");
        refused("http://example.com/a.wrl", "http: URLs are never fetched");
        refused("https://example.com/a.wrl", "https: URLs are never fetched");
        refused("file:///etc/passwd", "file: URLs are absolute");
        refused(outside.toString(), "absolute paths are not allowed");
        refused("../secret.wrl", "leads outside the allowed folder");
        refused("sub/../../secret.wrl", "leads outside the allowed folder");
        refused("C:/models/a.wrl", "absolute paths are not allowed");
        refused("missing.wrl", "not found");
        // the caller may allow a wider folder
        Path top = VrmlTesting.write(dir, "top.wrl", VrmlTesting.HEADER + "Inline { url \"../secret.wrl\" }\n");
        VrmlScene s = new VrmlLoader().allowFolder(dir.getParent()).load(top);
        assertEquals(12, TessellationWalk.mesh(s.getSceneGroup()).triangleCount());
        dir = dir.getParent();
    }

    @Test
    void inlineCycleIsAnError() throws IOException {
        VrmlTesting.write(dir, "b.wrl", VrmlTesting.HEADER + "Inline { url \"a.wrl\" }\n");
        Path a = VrmlTesting.write(dir, "a.wrl", VrmlTesting.HEADER + BOX + "\nInline { url \"b.wrl\" }\n");
        VrmlParseException e = assertThrows(VrmlParseException.class, () -> new VrmlLoader().load(a));
        assertTrue(e.getMessage().contains("b.wrl:2:14: Inline cycle"), e.getMessage());
    }

    private static void gzip(Path p, String text) throws IOException {
        try (OutputStream out = new GZIPOutputStream(Files.newOutputStream(p))) {
            out.write(text.getBytes(StandardCharsets.UTF_8));
        }
    }

    @Test
    void gzipIsRecognisedByContentWhateverTheName() throws IOException {
        gzip(dir.resolve("box.wrl"), VrmlTesting.HEADER + BOX);
        gzip(dir.resolve("sphere.wrz"), VrmlTesting.HEADER + "Shape { geometry Sphere { } }");
        Path top = VrmlTesting.write(dir, "top.wrl", VrmlTesting.HEADER + "Inline { url \"sphere.wrz\" }\n");
        assertEquals(12, TessellationWalk.mesh(new VrmlLoader().load(dir.resolve("box.wrl")).getSceneGroup()).triangleCount());
        assertTrue(TessellationWalk.mesh(new VrmlLoader().load(top).getSceneGroup()).isClosed());
        Files.write(dir.resolve("broken.wrl"), new byte[] {0x1f, (byte) 0x8b, 8, 0, 1, 2, 3});
        VrmlParseException e = assertThrows(VrmlParseException.class, () -> new VrmlLoader().load(dir.resolve("broken.wrl")));
        assertTrue(e.detail().contains("gzip signature"), e.getMessage());
    }

    @Test
    void loadsFromPathStringUrlAndReader() throws IOException {
        Path p = VrmlTesting.write(dir, "box.wrl", VrmlTesting.HEADER + BOX);
        assertNotNull(new VrmlLoader().load(p.toString()).getSceneGroup());
        assertNotNull(new VrmlLoader().load(p.toUri().toURL()).getSceneGroup());
        assertNotNull(new VrmlLoader().load(new java.io.StringReader(VrmlTesting.HEADER + BOX)).getSceneGroup());
        VrmlParseException e = assertThrows(VrmlParseException.class, () -> new VrmlLoader().load(new java.net.URL("http://example.com/x.wrl")));
        assertTrue(e.detail().contains("only file: URLs"), e.getMessage());
        VrmlParseException missing = assertThrows(VrmlParseException.class, () -> new VrmlLoader().load(dir.resolve("none.wrl")));
        assertEquals(dir.resolve("none.wrl") + ":1:1: cannot read the file: no such file", missing.getMessage());
    }

    @Test
    void sceneGoesLiveAndIsStillWalkable() {
        // flat-shaded IFS (more face normals than points), a USE'd shape (SharedGroup + Link),
        // a Switch: Java3D checks arrays and capabilities once the scene is live
        VrmlScene s = VrmlTesting.load("DEF S Shape { geometry IndexedFaceSet { coord Coordinate { point [ 0 0 0, 1 0 0, 0 1 0, 0 0 1 ] }"
            + " coordIndex [ 0 2 1 -1 0 1 3 -1 0 3 2 -1 1 2 3 -1 ] } }\n"
            + "Transform { translation 2 0 0 children USE S }\nSwitch { whichChoice 0 choice Shape { geometry Sphere { } } }\n");
        org.jogamp.java3d.VirtualUniverse u = new org.jogamp.java3d.VirtualUniverse();
        try {
            new org.jogamp.java3d.Locale(u).addBranchGraph(s.getSceneGroup());
            assertTrue(s.getSceneGroup().isLive());
            TessellationWalk.Result r = VrmlTesting.walk(s);
            assertEquals(3, r.shapes);
            assertEquals(8 + 2 * 32 + 32 * (16 - 2) * 2, r.merged().triangleCount());
        } finally {
            u.removeAllLocales();
        }
    }
}
