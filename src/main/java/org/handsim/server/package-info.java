/**
 * The resident server JVM that runs short commands on loaded, compiled code: the small
 * {@link org.handsim.server.Client} the launcher starts (JDK classes only on the path that hands
 * a command over), the {@link org.handsim.server.Server} that runs one command at a time for one
 * install, working directory, build and environment, and {@code handsim server status|stop}
 * ({@link org.handsim.server.ServerCommand}, {@link org.handsim.server.ServerAdmin}; DESIGN.md,
 * "Resident server"). It sits above {@code cli}, whose
 * commands it runs; nothing uses it.
 *
 * <p>May use every room below it, {@code cli} included (docs/DESIGN.md, "Modules").
 */
package org.handsim.server;
