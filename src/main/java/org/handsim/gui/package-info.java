/**
 * The desktop program (paper Section V, Fig. 5): a Swing window with the paper's Kinematics,
 * Path Planning, Dynamics and Objects buttons, a Java3D view of the hand, the object and the
 * contacts, live JFreeChart traces, Play / Pause / Step / Reset, menus and shortcuts, and a
 * scripted mode for tests and documentation ({@link org.handsim.gui.Script}). The simulator
 * itself — view and model — is one embeddable component, {@link org.handsim.gui.HandSimPanel};
 * {@link org.handsim.gui.HandSimWindow} is built around it. Nothing outside {@code gui} and
 * {@code cli} uses this package (the README's embedding example aside).
 *
 * <h2>Thread rules</h2>
 * <ol>
 *   <li><b>The model has one thread.</b> Only the simulation thread of
 *       {@link org.handsim.gui.SimulationRunner} creates, initialises and steps the
 *       {@code HandModel}. Other threads send it commands (load, play, pause, step, reset,
 *       speed), which it runs in order.</li>
 *   <li><b>Views read immutable values.</b> The simulation thread publishes a
 *       {@link org.handsim.gui.SimulationRunner.State} (holding a {@code model.Snapshot}) through
 *       a volatile field and trace rows through a concurrent queue; nothing published is
 *       changed afterwards.</li>
 *   <li><b>Swing and the scene graph belong to the event dispatch thread.</b> A
 *       {@code javax.swing.Timer} on the EDT reads the newest state at display rate and updates
 *       the 3D view, charts, labels and tables; panels change the working scenario there. Java3D
 *       renders on its own threads from the scene graph the EDT edits (the frame-rate
 *       measurement's spin behaviour runs on Java3D's behaviour thread).</li>
 *   <li><b>The grasp has a thread too.</b> At each publication the simulation thread hands
 *       {@link org.handsim.gui.LiveGrasp} a copy of what a grasp evaluation reads
 *       ({@code grasp.GraspAssessment.Input}) when the contacts changed, without waiting; the
 *       grasp thread evaluates the newest copy at most 10 times a second and publishes an
 *       immutable result through a volatile field, which the EDT's timer shows.</li>
 *   <li><b>Nothing slow on the EDT.</b> Stepping, the grasp evaluation, and reading VRML files
 *       run on other threads; the EDT never waits for the model. Scripts run on their own thread and reach the EDT
 *       with {@code invokeAndWait}.</li>
 *   <li><b>Scripts see one state.</b> A scripted window holds its model between actions
 *       ({@link org.handsim.gui.SimulationRunner#hold}: it steps only during {@code play} and
 *       {@code wait}), and a screenshot or log waits until every readout shows the newest state
 *       ({@code ScriptRunner.settle}), so one script gives one picture on any machine.</li>
 *   <li><b>Errors are shown, not lost.</b> A {@code SimulationException} stops the run and
 *       appears in the status bar and a dialog; uncaught exceptions (on the EDT or elsewhere)
 *       are recorded by {@link org.handsim.gui.ErrorLog} and make a scripted run fail.</li>
 * </ol>
 *
 * <p>May use every room below it (docs/DESIGN.md, "Modules").
 */
package org.handsim.gui;
