package org.handsim.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.nio.file.Files;
import java.nio.file.Path;
import org.handsim.cli.ChildJvm;
import org.handsim.mesh.TriangleMesh;
import org.handsim.process.CommandContext;
import org.junit.jupiter.api.Test;

/**
 * The in-memory mesh cache in a JVM that runs many commands (the resident server): a file's mesh
 * is made once per command at most, and a file edited between two commands gives the next
 * command its new mesh, never the one cached from the old bytes.
 */
class MeshCheckedPerCommandTest {
    private static String triangles(int n) {
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < n; i++) {
            sb.append("v ").append(i).append(" 0 0\nv ").append(i + 1).append(" 0 0\nv ").append(i).append(" 1 0\n");
            sb.append("f ").append(3 * i + 1).append(' ').append(3 * i + 2).append(' ').append(3 * i + 3).append('\n');
        }
        return sb.toString();
    }

    @Test
    void anEditedFileIsLoadedAgainByTheNextCommandOnly() throws Exception {
        Path dir = Files.createTempDirectory("handsim-mesh-generation");
        try {
            Path f = dir.resolve("plate.obj");
            Files.writeString(f, triangles(1));
            CommandContext.begin(false);
            TriangleMesh first = SceneMeshes.mesh(f, 8, 1.0);
            assertEquals(1, first.triangleCount());
            Files.writeString(f, triangles(3));
            assertSame(first, SceneMeshes.mesh(f, 8, 1.0), "within one command the file is read once");
            CommandContext.end();
            CommandContext.begin(false);   // the next command
            TriangleMesh second = SceneMeshes.mesh(f, 8, 1.0);
            assertEquals(3, second.triangleCount(), "the edited file's mesh");
            CommandContext.end();
            CommandContext.begin(false);   // unchanged file: the cached mesh
            assertSame(second, SceneMeshes.mesh(f, 8, 1.0));
            CommandContext.end();
        } finally {
            CommandContext.end();
            ChildJvm.deleteTree(dir);
        }
    }
}
