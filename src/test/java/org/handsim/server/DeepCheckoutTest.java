package org.handsim.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.handsim.TestPaths;
import org.handsim.cli.ChildJvm;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The battery's deep checkout: cloned 36 characters deep, {@code .ci/run} failed five
 * {@code ServerTest} cases ("Unix domain path too long": the tests put the servers' folder in the
 * build folder, and the JDK binds a socket path of at most 106 bytes). Here the repository is cloned 120
 * characters deep and the clone's own build runs every server test there, which must all pass.
 */
@Tag("slow")
class DeepCheckoutTest {
    @Test
    void theServerTestsPassInACheckout120CharactersDeep() throws Exception {
        Path root = TestPaths.root();
        Assumptions.assumeTrue(Files.isDirectory(root.resolve(".git")) || Files.isRegularFile(root.resolve(".git")), "a git checkout");
        Path top = Files.createTempDirectory(Path.of("/tmp"), "handsim-deep");
        try {
            Path deep = top;
            while (deep.toString().length() < 120) deep = deep.resolve("a-checkout-deep-in-folders");
            Files.createDirectories(deep.getParent());
            assertTrue(deep.toString().length() >= 120, deep.toString());
            run(top, 10, "git", "clone", "--quiet", "--no-hardlinks", root.toString(), deep.toString());
            String out = run(deep, 60, "gradle", "--console=plain", "--offline", "test",
                "-Ptests=ServerTest|ServedAsInProcessTest|ServedLikeInProcessTest|ClientFolderTest", "-Dhandsim.shared=" + TestPaths.shared());
            Matcher m = Pattern.compile("(?m)^([0-9]+) passed, ([0-9]+) failed$").matcher(out);
            assertTrue(m.find(), out);
            assertEquals("0", m.group(2), out);
            assertTrue(Integer.parseInt(m.group(1)) >= 15, out);
            System.out.println("DeepCheckoutTest: " + m.group() + " in a checkout " + deep.toString().length() + " characters deep");
        } finally {
            ChildJvm.deleteTree(top);
        }
    }

    /** Runs a command in {@code dir} to its end; its output (standard error with it). */
    private static String run(Path dir, long minutes, String... cmd) throws Exception {
        Process p = new ProcessBuilder(List.of(cmd)).directory(dir.toFile()).redirectErrorStream(true).start();
        StringBuilder out = new StringBuilder();
        Thread reader = new Thread(() -> {
            try {
                out.append(new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8));
            } catch (java.io.IOException e) {
                out.append(e);
            }
        });
        reader.start();
        if (!p.waitFor(minutes, TimeUnit.MINUTES)) {
            p.destroyForcibly().waitFor();
            fail(String.join(" ", cmd) + " did not end within " + minutes + " minutes");
        }
        reader.join();
        if (p.exitValue() != 0 && !cmd[0].equals("gradle")) fail(String.join(" ", cmd) + ": exit " + p.exitValue() + "\n" + out);
        return out.toString();
    }
}
