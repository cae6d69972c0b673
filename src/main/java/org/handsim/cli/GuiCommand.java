package org.handsim.cli;

import org.handsim.scenario.NotFound;
import java.awt.GraphicsEnvironment;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.handsim.gui.GuiLauncher;
import org.handsim.gui.Script;
import org.handsim.scenario.Home;
import org.handsim.scenario.Scenario;
import org.handsim.files.InputFile;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code handsim gui}: the desktop program (Swing + Java3D), interactive or scripted. */
@Command(name = "gui", mixinStandardHelpOptions = true,
    description = {"Opens the simulator's window (paper Fig. 5).",
        "It has the Kinematics, Path Planning, Dynamics and Objects panels,",
        "Play/Pause/Step/Reset, the 3D view of the hand",
        "and the object with contact points and normals (mouse: left drag orbits,",
        "wheel or middle drag zooms, right drag pans) and live joint traces.",
        "Default scenario: the paper's experiment, scenarios/paper-breakaway.json.",
        "Menus File (open/save scenario, import object, export traces, save charts,",
        "screenshot), View (camera, contacts, series) and Run; keys: Space play/pause,",
        "Right step, R reset, H/F/1/2/3 camera, Ctrl+O/S/I/E.",
        "It needs a display. Without one, use a virtual display:",
        "  xvfb-run -a -s '-screen 0 1280x1024x24' handsim gui ...",
        "or ./handsim gui, which starts Xvfb itself. With --script, --screenshot or",
        "--measure-fps it runs unattended and exits when done."},
    footer = {"", Script.HELP})
public final class GuiCommand implements Callable<Integer> {
    @Spec CommandSpec spec;

    @Parameters(index = "0", arity = "0..1", paramLabel = "SCENARIO", description = "scenario JSON file")
    Path scenarioFile;

    @Option(names = "--script", paramLabel = "ACTIONS.txt", description = "run these actions (see below), then exit")
    Path script;

    @Option(names = "--screenshot", paramLabel = "OUT.png", description = "save the whole window as PNG at the end, then exit")
    Path screenshot;

    @Option(names = "--measure-fps", paramLabel = "SECONDS",
        description = "at the end, render continuously for SECONDS and print the frames per second, then exit")
    Double measureFps;

    @Option(names = "--object", paramLabel = "FILE", description = "import this object (.wrl, .obj, .stl) at the start, as the Objects panel does")
    Path object;

    @Option(names = "--speed", paramLabel = "FACTOR|max", description = "simulation speed: 1 = real time (default), max = as fast as possible")
    String speed;

    @Override
    public Integer call() throws InterruptedException {
        PrintWriter out = spec.commandLine().getOut(), err = spec.commandLine().getErr();
        Double speedFactor = null;
        if (speed != null) {
            if (speed.equalsIgnoreCase("max")) {
                speedFactor = 0.0;
            } else {
                try {
                    speedFactor = org.handsim.text.Decimal.parse(speed);
                } catch (NumberFormatException e) {
                    speedFactor = Double.NaN;
                }
                if (!(speedFactor > 0) || speedFactor.isInfinite()) throw CliError.usage("handsim: --speed must be a number > 0 or max, got '" + speed + "'");
            }
        }
        if (measureFps != null && !(measureFps > 0 && measureFps <= 3600)) {
            throw CliError.usage("handsim: --measure-fps must be in (0, 3600] seconds, got " + Args.typed(spec, "--measure-fps"));
        }
        Script actions = null;
        if (script != null) {
            Args.inputFile(script);   // says where a relative path was looked for
            String text = InputFile.readText(script, Script.MAX_BYTES, "the limit of window scripts");
            try {
                actions = Script.parse(script.toString(), text);
            } catch (Script.ScriptException e) {
                throw CliError.usage("handsim: " + e.getMessage());
            }
        }
        Scenario scenario = RunCommand.loadScenario(scenarioFile != null ? scenarioFile : Home.paperScenario(), "handsim gui", err);
        if (GraphicsEnvironment.isHeadless()) {
            throw CliError.usage("handsim gui: no display (DISPLAY is not set or Java runs headless): run it under a virtual display with "
                + "xvfb-run -a -s '-screen 0 1280x1024x24' handsim gui ..., or use ./handsim gui, which starts Xvfb itself");
        }
        if (object != null) {
            String why = NotFound.problem(object);
            if (why != null) throw new CliError(CliError.LOAD, "handsim: --object " + object + ": " + why);
        }
        Path scriptDir = script != null ? script.toAbsolutePath().getParent() : null;
        return GuiLauncher.run(new GuiLauncher.Options(scenario, actions, scriptDir, screenshot, measureFps, speedFactor, object), out, err);
    }
}
