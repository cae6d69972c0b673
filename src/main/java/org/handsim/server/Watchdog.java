package org.handsim.server;

import java.io.IOException;
import java.nio.channels.SocketChannel;

/**
 * Closes a channel whose peer has not started answering in time — a blocked connect, send or
 * first read then ends at once — unless disarmed first: a server stopped with SIGSTOP, swapped
 * out or wedged costs its caller this long, never more. A class, not a lambda: a client's
 * start-up spins none.
 */
final class Watchdog extends Thread {
    private final SocketChannel ch;
    final long ms;
    private long end;
    private boolean disarmed;
    volatile boolean fired;

    /** Arms it (the thread starts here). */
    Watchdog(SocketChannel ch, long ms) {
        super("handsim-watchdog");
        setDaemon(true);
        this.ch = ch;
        this.ms = ms;
        this.end = System.nanoTime() + ms * 1_000_000;
        start();
    }

    @Override
    public void run() {
        synchronized (this) {
            for (long left = ms; left > 0 && !disarmed; left = (end - System.nanoTime()) / 1_000_000) {
                try {
                    wait(Math.max(1, left));
                } catch (InterruptedException e) {
                    return;
                }
            }
            if (disarmed) return;
            fired = true;
        }
        try {
            ch.close();
        } catch (IOException e) {
            // closed already
        }
    }

    /** Gives the peer {@code more} ms from now (it has said it is alive and why it waits); false if it had fired already. */
    synchronized boolean extend(long more) {
        end = System.nanoTime() + more * 1_000_000;
        notifyAll();
        return !fired;
    }

    /** Disarms it; false if it had fired already. */
    synchronized boolean disarm() {
        disarmed = true;
        notifyAll();
        return !fired;
    }
}
