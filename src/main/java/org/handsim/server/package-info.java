/**
 * The resident server JVM that runs short commands on loaded, compiled code: the small
 * {@link org.handsim.server.Client} the launcher starts (JDK classes only on the path that hands
 * a command over), the {@link org.handsim.server.Server} that runs one command at a time for one
 * install, working directory, build and environment, and {@link org.handsim.server.ServerAdmin}
 * behind {@code handsim server status|stop}. DESIGN.md, "Resident server".
 */
package org.handsim.server;
