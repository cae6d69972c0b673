package org.handsim.server;

import java.io.IOException;
import java.io.PrintWriter;
import java.util.List;
import java.util.concurrent.Callable;
import org.handsim.cli.CliError;
import org.handsim.scenario.Home;
import org.handsim.text.SafeText;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code handsim server status|stop}: the resident servers that run short commands (DESIGN.md, "Resident server"). */
@Command(name = "server", mixinStandardHelpOptions = true,
    description = {"Shows or stops the resident servers of this install (--all: of every install).",
        "The ./handsim launcher hands short commands (run, sweep, plan, mesh, collide,",
        "fk, ik, id, swing, grasp, quality) to a server JVM of this install, working",
        "directory, build and environment when one is running and free, and otherwise",
        "runs them itself and starts one for next time. A command that names the",
        "client's own descriptors (/dev/stdout, /proc/self/...) runs in the client. At",
        "most 2 servers per user (HANDSIM_SERVER_MAX), the least recently used stopped",
        "first; a server exits after 10 minutes without a command, within a second when",
        "the build changes or its install goes. HANDSIM_SERVER=0 turns this off.",
        "status: one line per server (pid, working directory, state, memory, log) and",
        "why the last command was not served; stop: each stops after its running command."})
public final class ServerCommand implements Callable<Integer> {
    @Spec CommandSpec spec;

    @Parameters(index = "0", paramLabel = "status|stop", description = "what to do")
    String action;

    @picocli.CommandLine.Option(names = "--all", description = "every server of this user, of any install (a moved or deleted checkout's too)")
    boolean all;

    @Override
    public Integer call() throws IOException {
        PrintWriter out = spec.commandLine().getOut();
        if (!action.equals("status") && !action.equals("stop")) {
            throw CliError.usage("handsim server: the action must be status or stop, got " + SafeText.quote(action));
        }
        String unsafe = ServerAdmin.unsafe();
        if (unsafe != null) {
            out.println("no server can run: " + unsafe + " (the folder must be the user's alone, mode 700)");
            return 0;
        }
        String home = Home.dir().toAbsolutePath().normalize().toString();
        List<ServerAdmin.Status> servers = ServerAdmin.servers();
        int n = 0;
        for (ServerAdmin.Status s : servers) {
            if (!all && !home.equals(s.field("home"))) continue;   // another install's
            n++;
            String cwd = s.field("cwd");
            int sp = cwd.lastIndexOf(' ');
            if (sp > 0) cwd = cwd.substring(0, sp);   // without the folder's inode
            if (action.equals("status")) {
                out.println(SafeText.line("pid " + s.field("pid") + ": " + s.field("state") + ", working directory " + cwd + ", " + s.field("commands")
                    + " commands since " + s.field("since") + ", " + megabytes(s.field("memory")) + " resident, log " + s.field("log")
                    + (all ? ", install " + s.field("home") : "")));
            } else {
                out.println(SafeText.line((ServerAdmin.stop(s.socket()) ? "stopping" : "already gone:") + " pid " + s.field("pid")
                    + " (working directory " + cwd + ")"));
            }
        }
        if (n == 0) out.println(SafeText.line("no server running for " + (all ? "this user" : home) + (System.getenv("HANDSIM_SERVER") != null
            && System.getenv("HANDSIM_SERVER").equals("0") ? " (HANDSIM_SERVER=0: none is started)" : "")));
        String why = ServerAdmin.lastNotServed();
        if (action.equals("status") && why != null) out.println(SafeText.line("last command not served: " + why));
        return 0;
    }

    /** A byte count as whole megabytes ("? MB" if unknown). */
    private static String megabytes(String bytes) {
        try {
            return (Long.parseLong(bytes) >> 20) + " MB";
        } catch (NumberFormatException e) {
            return "? MB";
        }
    }
}
