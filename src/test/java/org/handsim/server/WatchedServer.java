package org.handsim.server;

import org.handsim.testing.PhaseWatch;

/** A resident server whose commands' named points the tests watch ({@link PhaseWatch}): the main of ServerTest's servers. */
public final class WatchedServer {
    private WatchedServer() {}

    public static void main(String[] args) throws Exception {
        PhaseWatch.installIfAsked();
        Server.main(args);
    }
}
