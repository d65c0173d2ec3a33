package angularkinematics;

import java.io.File;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import no.ntnu.ihb.fmi4j.FmiStatus;
import no.ntnu.ihb.fmi4j.importer.fmi2.Fmu;
import no.ntnu.ihb.fmi4j.importer.fmi2.ModelExchangeInstance;
import no.ntnu.ihb.fmi4j.importer.fmi2.CoSimulationSlave;
import no.ntnu.ihb.fmi4j.importer.fmi2.AbstractModelInstance;
import no.ntnu.ihb.fmi4j.modeldescription.variables.Causality;
import no.ntnu.ihb.fmi4j.modeldescription.variables.RealVariable;

/**
 * Runs one FMI 2 FMU through FMI4j over the inputs of a CSV file and writes every Real output.
 *
 *   java -jar fmi4j-driver.jar FMU cs|me INPUT.csv OUTPUT.csv
 *
 * INPUT.csv: a header "time","<input>",... and one row per communication point. At each row the
 * driver sets the inputs (after fmi2SetTime in Model Exchange), reads the outputs, then (Co-Simulation)
 * steps to the next row's time, or (Model Exchange with continuous states) takes one explicit Euler
 * step to it: the call sequence of examples/cross_check.py, so that the two
 * importers must give the same numbers. OUTPUT.csv: "time", the Real outputs in the order of the
 * model description, and "status", the worst status of that row's calls. %.17g round-trips a double.
 * Exit status 1 when any call returns anything but fmi2OK.
 */
public final class FmuRun {
    private static FmiStatus worst = FmiStatus.OK;

    private static FmiStatus check(FmiStatus status, String call) {
        if (status != FmiStatus.OK) {
            System.err.println(call + ": " + status);
        }
        if (status.getCode() > worst.getCode()) {
            worst = status;
        }
        return status;
    }

    private static FmiStatus check(boolean ok, AbstractModelInstance<?, ?> instance, String call) {
        return check(ok ? FmiStatus.OK : instance.getLastStatus(), call);
    }

    public static void main(String[] args) throws IOException {
        if (args.length != 4 || !(args[1].equals("cs") || args[1].equals("me"))) {
            System.err.println("usage: java -jar fmi4j-driver.jar FMU cs|me INPUT.csv OUTPUT.csv");
            System.exit(2);
        }
        List<String> lines = Files.readAllLines(new File(args[2]).toPath());
        // Quoted names, split between quotes: a name such as R[1,2] holds a comma.
        String first = lines.get(0).trim();
        String[] header = first.substring(1, first.length() - 1).split("\",\"");
        int rows = lines.size() - 1;
        double[][] table = new double[rows][header.length];
        for (int r = 0; r < rows; r++) {
            String[] cells = lines.get(r + 1).split(",");
            for (int c = 0; c < header.length; c++) {
                table[r][c] = Double.parseDouble(cells[c]);
            }
        }

        try (Fmu fmu = Fmu.from(new File(args[0]))) {
            boolean coSimulation = args[1].equals("cs");
            AbstractModelInstance<?, ?> instance = coSimulation
                ? (CoSimulationSlave) fmu.asCoSimulationFmu().newInstance("fmi4j")
                : fmu.asModelExchangeFmu().newInstance("fmi4j");
            var variables = instance.getModelDescription().getModelVariables();
            long[] inputs = new long[header.length - 1];
            for (int c = 1; c < header.length; c++) {
                inputs[c - 1] = variables.getValueReference(header[c]);
            }
            List<String> outputNames = new ArrayList<>();
            List<Long> outputList = new ArrayList<>();
            for (RealVariable v : variables.getReals()) {
                if (v.getCausality() == Causality.OUTPUT) {
                    outputNames.add(v.getName());
                    outputList.add(v.getValueReference());
                }
            }
            long[] outputs = outputList.stream().mapToLong(Long::longValue).toArray();
            int states = instance.getModelDescription().getNumberOfContinuousStates();
            double[] x = new double[states];
            double[] dx = new double[states];

            double start = table[0][0], stop = table[rows - 1][0];
            check(instance.setupExperiment(start, stop, 0.0), instance, "fmi2SetupExperiment");
            check(instance.enterInitializationMode(), instance, "fmi2EnterInitializationMode");
            check(instance.exitInitializationMode(), instance, "fmi2ExitInitializationMode");
            ModelExchangeInstance me = coSimulation ? null : (ModelExchangeInstance) instance;
            if (me != null) {
                check(me.newDiscreteStates(), "fmi2NewDiscreteStates");
                check(me.enterContinuousTimeMode(), "fmi2EnterContinuousTimeMode");
            }

            double[] in = new double[inputs.length];
            double[] out = new double[outputs.length];
            try (PrintWriter writer = new PrintWriter(args[3], "UTF-8")) {
                StringBuilder head = new StringBuilder("\"time\"");
                for (String name : outputNames) {
                    head.append(",\"").append(name).append('"');
                }
                writer.println(head.append(",\"status\""));
                for (int r = 0; r < rows; r++) {
                    FmiStatus before = worst;
                    worst = FmiStatus.OK;
                    double time = table[r][0];
                    if (me != null) {
                        check(me.setTime(time), "fmi2SetTime");
                    }
                    System.arraycopy(table[r], 1, in, 0, in.length);
                    check(instance.writeReal(inputs, in), "fmi2SetReal");
                    check(instance.readReal(outputs, out), "fmi2GetReal");
                    StringBuilder row = new StringBuilder(String.format(Locale.ROOT, "%.17g", time));
                    for (double value : out) {
                        row.append(',').append(String.format(Locale.ROOT, "%.17g", value));
                    }
                    if (coSimulation && r + 1 < rows) {
                        check(((CoSimulationSlave) instance).doStep(time, table[r + 1][0] - time),
                              instance, "fmi2DoStep");
                    }
                    if (me != null && states > 0 && r + 1 < rows) {
                        // One explicit Euler step to the next row, as examples/cross_check.py.
                        double h = table[r + 1][0] - time;
                        check(me.getContinuousStates(x), "fmi2GetContinuousStates");
                        check(me.getDerivatives(dx), "fmi2GetDerivatives");
                        for (int k = 0; k < states; k++) {
                            x[k] = x[k] + h * dx[k];
                        }
                        check(me.setContinuousStates(x), "fmi2SetContinuousStates");
                        me.completedIntegratorStep();
                        check(me.getLastStatus(), "fmi2CompletedIntegratorStep");
                    }
                    writer.println(row.append(',').append(worst.name()));
                    if (before.getCode() > worst.getCode()) {
                        worst = before;
                    }
                }
            }
            check(instance.terminate(), instance, "fmi2Terminate");
        }
        System.exit(worst == FmiStatus.OK ? 0 : 1);
    }
}
