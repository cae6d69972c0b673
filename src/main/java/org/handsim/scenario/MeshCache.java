package org.handsim.scenario;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.FileTime;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;
import java.util.zip.CRC32C;
import java.util.zip.GZIPInputStream;
import org.handsim.mesh.TriangleMesh;
import org.handsim.files.InputFile;
import org.handsim.files.PrivateFolder;

/**
 * A folder of triangle meshes already tessellated, so that a command in a new JVM reads an
 * object or a hand link in a millisecond instead of parsing its file and building a Java3D scene
 * (which, with the classes it loads, was most of {@code handsim run}'s load phase).
 *
 * <p><b>Key.</b> The file's bytes (not its name or time: a copied or touched file still hits, an
 * edited one misses), the divisions and scale it is tessellated at, and the identity of the code
 * that tessellates (the jars of HandSim and Java3D: path, size and time, and the Java version),
 * so a new build never reads meshes an older one made. The entry's name comes from two CRCs of
 * the bytes and the rest of the key; the entry holds the whole key and the file's bytes, and a
 * hit needs both equal — an exact test, where a cryptographic hash of the file cost more than
 * the rest of the lookup (SHA-256 runs interpreted in a fresh JVM). Files that may
 * read other files (VRML with {@code Inline} or {@code EXTERNPROTO}) are not cached, nor is
 * anything when HandSim runs from class folders (tests, IDEs) unless the folder is set
 * explicitly.
 *
 * <p><b>Folder.</b> System property {@code handsim.cache} (a folder, or {@code off}), else
 * {@code $XDG_CACHE_HOME/handsim}, else {@code ~/.cache/handsim}; meshes go to its
 * {@code meshes/}. At most {@value #MAX_BYTES} bytes are kept: when a write passes that, the
 * least recently used entries go (reads refresh an entry's time).
 *
 * <p><b>Safety.</b> An entry is {@code magic, key, file bytes, name, vertices, triangles, CRC-32C
 * of all before}; an entry whose magic, key, file bytes, sizes or checksum do not match (a torn
 * write, a disk error, another version, another file of the same CRCs) is a miss and is replaced. Writers write a temporary file of their
 * own and rename it onto the entry's name atomically, so concurrent writers of the same mesh
 * (identical bytes) and readers never see a partial entry. Every failure of the cache itself
 * (no home folder, a read-only disk) only means tessellating again: it never fails a command.
 */
public final class MeshCache {
    /** Most bytes of cached meshes kept on disk. */
    static final long MAX_BYTES = 256L << 20;
    private static final byte[] MAGIC = "HandSim mesh 2\n".getBytes(StandardCharsets.US_ASCII);
    private static volatile String codeIdentity;

    private MeshCache() {}

    /**
     * The mesh of {@code file}, whose bytes the caller read ({@link MeshFiles#read}), at these
     * divisions and scale: from the cache folder, or made by {@code load} (and stored). The file
     * is not read here.
     */
    public static TriangleMesh get(Path file, byte[] bytes, int divisions, double scale, Supplier<TriangleMesh> load) {
        Path dir = folder();
        // entries are trusted (their mesh is not made again), so only from a folder nobody else may write
        if (dir == null || !PrivateFolder.ensure(dir)) return load.get();
        Path entry;
        String key;
        try {
            if (!selfContained(file, bytes)) return load.get();
            key = key(divisions, scale);
            entry = dir.resolve(name(bytes, key));
            TriangleMesh hit = read(entry, key, bytes);
            if (hit != null) return hit;
        } catch (IOException | RuntimeException e) {
            return load.get();   // unreadable here: let the loader say why, in its words
        }
        TriangleMesh m = load.get();
        write(dir, entry, key, bytes, m);
        return m;
    }

    /** The cache folder ({@code meshes/} inside the user's HandSim cache), or null when off. */
    static Path folder() {
        String p = System.getProperty("handsim.cache");
        if (p != null) return p.isBlank() || p.equalsIgnoreCase("off") ? null : Path.of(p, "meshes");
        if (codeIdentity() == null) return null;   // class folders: the code can change without a new identity
        String xdg = System.getenv("XDG_CACHE_HOME");
        Path base = xdg != null && !xdg.isBlank() ? Path.of(xdg) : Path.of(System.getProperty("user.home", ""), ".cache");
        return base.isAbsolute() ? base.resolve("handsim").resolve("meshes") : null;
    }

    /** Whether the mesh of a file depends on that file alone (OBJ, STL, VRML without Inline or EXTERNPROTO). */
    static boolean selfContained(Path file, byte[] bytes) throws IOException {
        if (MeshFiles.Format.of(file) != MeshFiles.Format.VRML) return true;
        byte[] text = bytes;
        if (bytes.length >= 2 && (bytes[0] & 0xff) == 0x1f && (bytes[1] & 0xff) == 0x8b) {
            try (InputStream in = new GZIPInputStream(new ByteArrayInputStream(bytes))) {
                text = in.readNBytes(64 << 20);
            }
        }
        String s = new String(text, StandardCharsets.ISO_8859_1);
        return !s.contains("Inline") && !s.contains("EXTERNPROTO");
    }

    /** The key but for the file's bytes: how it is tessellated and by which code. */
    static String key(int divisions, double scale) {
        return "divisions " + divisions + " scale " + Double.doubleToLongBits(scale) + " code " + (codeIdentity() == null ? "classes" : codeIdentity());
    }

    /** The entry's file name: the file's length and two CRCs of it, and a hash of the rest of the key. */
    static String name(byte[] bytes, String key) {
        CRC32C c = new CRC32C();
        c.update(bytes);
        java.util.zip.CRC32 d = new java.util.zip.CRC32();
        d.update(bytes);
        return Long.toHexString(c.getValue() << 32 | d.getValue()) + "-" + Integer.toHexString(bytes.length) + "-"
            + Integer.toHexString(key.hashCode()) + ".mesh";
    }

    /** The jars the tessellation comes from (path, size, time) and the Java version; null when running from class folders. */
    static String codeIdentity() {
        String id = codeIdentity;
        if (id != null) return id.isEmpty() ? null : id;
        StringBuilder sb = new StringBuilder(System.getProperty("java.version", "?"));
        // by resource, not by class: naming a Java3D class here would load Java3D, which the cache is there to avoid
        for (String cls : new String[] {"org/handsim/scenario/MeshCache.class", "org/jogamp/java3d/Shape3D.class"}) {
            try {
                java.net.URL u = MeshCache.class.getClassLoader().getResource(cls);
                String path = u == null || !"jar".equals(u.getProtocol()) ? null : u.getPath();
                if (path == null || !path.contains("!/")) {
                    codeIdentity = "";
                    return null;
                }
                Path jar = Path.of(java.net.URI.create(path.substring(0, path.indexOf("!/"))));
                sb.append(' ').append(jar.toAbsolutePath()).append(':').append(Files.size(jar)).append(':').append(Files.getLastModifiedTime(jar).toMillis());
            } catch (IOException | RuntimeException e) {   // not a file URL (a custom class loader): no cache
                codeIdentity = "";
                return null;
            }
        }
        codeIdentity = sb.toString();
        return codeIdentity;
    }

    /** The mesh of an entry, or null if it is missing, is of another key or file, or does not check out. */
    static TriangleMesh read(Path entry, String key, byte[] source) {
        byte[] b;
        try {
            if (!Files.exists(entry)) return null;
            b = InputFile.readBytes(entry, MAX_BYTES, "the mesh cache's limit");
        } catch (InputFile.InputFileException e) {
            return null;
        }
        try {
            ByteBuffer in = ByteBuffer.wrap(b);
            if (b.length < MAGIC.length + 8) return null;
            for (byte m : MAGIC) if (in.get() != m) return null;
            CRC32C crc = new CRC32C();
            crc.update(b, 0, b.length - 8);
            if (crc.getValue() != ByteBuffer.wrap(b, b.length - 8, 8).getLong()) return null;
            if (!key.equals(string(in))) return null;
            int ns = in.getInt();
            if (ns != source.length || ns > in.remaining()) return null;
            if (!java.util.Arrays.equals(b, in.position(), in.position() + ns, source, 0, ns)) return null;
            in.position(in.position() + ns);
            String name = string(in);
            int nv = in.getInt();
            if (nv < 0 || nv > in.remaining() / 8) return null;
            double[] v = new double[nv];
            in.asDoubleBuffer().get(v);
            in.position(in.position() + 8 * nv);
            int nt = in.getInt();
            if (nt < 0 || nt % 3 != 0 || nt > in.remaining() / 4) return null;
            int[] t = new int[nt];
            in.asIntBuffer().get(t);
            in.position(in.position() + 4 * nt);
            if (in.remaining() != 8) return null;
            for (int i : t) if (i < 0 || 3 * i >= nv) return null;
            try {
                Files.setLastModifiedTime(entry, FileTime.fromMillis(System.currentTimeMillis()));   // recently used
            } catch (IOException e) {
                // a read-only cache still serves
            }
            return new TriangleMesh(name, v, t);
        } catch (RuntimeException e) {   // truncated: a buffer underflow
            return null;
        }
    }

    /** Stores a mesh under its entry (temporary file, then an atomic rename); failures are ignored. */
    static void write(Path dir, Path entry, String key, byte[] source, TriangleMesh m) {
        byte[] k = key.getBytes(StandardCharsets.UTF_8), n = m.name().getBytes(StandardCharsets.UTF_8);
        double[] v = m.vertices();
        int[] t = m.triangles();
        ByteBuffer out = ByteBuffer.allocate(MAGIC.length + 4 + k.length + 4 + source.length + 4 + n.length + 4 + 8 * v.length + 4 + 4 * t.length + 8);
        out.put(MAGIC).putInt(k.length).put(k).putInt(source.length).put(source).putInt(n.length).put(n).putInt(v.length);
        out.asDoubleBuffer().put(v);
        out.position(out.position() + 8 * v.length);
        out.putInt(t.length);
        out.asIntBuffer().put(t);
        out.position(out.position() + 4 * t.length);
        CRC32C crc = new CRC32C();
        crc.update(out.array(), 0, out.position());
        out.putLong(crc.getValue());
        Path tmp = null;
        try {
            Files.createDirectories(dir);
            tmp = Files.createTempFile(dir, ".mesh-", ".tmp");
            Files.write(tmp, out.array());
            try {
                Files.move(tmp, entry, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(tmp, entry, StandardCopyOption.REPLACE_EXISTING);
            }
            tmp = null;
            trim(dir, entry);
        } catch (IOException | RuntimeException e) {
            // no cache this time
        } finally {
            if (tmp != null) {
                try {
                    Files.deleteIfExists(tmp);
                } catch (IOException e) {
                    // left for the next trim
                }
            }
        }
    }

    /** Deletes the least recently used entries (and stale temporary files) while the folder holds more than {@link #MAX_BYTES}. */
    static void trim(Path dir, Path keep) throws IOException {
        List<Path> entries = new ArrayList<>();
        try (var s = Files.list(dir)) {
            s.filter(p -> p.getFileName().toString().endsWith(".mesh") || p.getFileName().toString().endsWith(".tmp")).forEach(entries::add);
        }
        long total = 0;
        List<Object[]> sized = new ArrayList<>();
        for (Path p : entries) {
            try {
                long size = Files.size(p), time = Files.getLastModifiedTime(p).toMillis();
                total += size;
                sized.add(new Object[] {p, size, time});
            } catch (IOException e) {
                // gone meanwhile (another process trims too)
            }
        }
        if (total <= MAX_BYTES) return;
        sized.sort((a, b) -> Long.compare((long) a[2], (long) b[2]));
        for (Object[] e : sized) {
            if (total <= MAX_BYTES) break;
            Path p = (Path) e[0];
            if (p.equals(keep)) continue;
            if (Files.deleteIfExists(p)) total -= (long) e[1];
        }
    }

    private static String string(ByteBuffer in) {
        int n = in.getInt();
        if (n < 0 || n > in.remaining()) throw new IllegalArgumentException("bad length");
        byte[] s = new byte[n];
        in.get(s);
        return new String(s, StandardCharsets.UTF_8);
    }
}
