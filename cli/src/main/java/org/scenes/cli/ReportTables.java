package org.scenes.cli;

import java.io.PrintWriter;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.ToDoubleFunction;
import org.scenes.app.validate.Validation;
import org.scenes.api.ActionLabel;
import org.scenes.api.ActionType;
import org.scenes.internal.validate.Folds;
import org.scenes.internal.validate.ValidationReport;

/** The terminal form of validation results. */
final class ReportTables {
    private ReportTables() {
    }

    static void print(PrintWriter out, List<Validation.Outcome> outcomes) {
        for (Validation.Outcome outcome : outcomes) {
            out.println("== " + outcome.label());
            if (outcome.report() != null) {
                printRun(out, outcome.report());
            } else {
                printFolds(out, outcome.folds());
            }
            out.println();
        }
        if (outcomes.size() > 1) {
            out.printf("%-60s %9s %9s %9s %9s%n", "Configuration", "Action%", "Majority%", "Previous%", "Kick%");
            for (Validation.Outcome outcome : outcomes) {
                ValidationReport pooled = outcome.report() != null ? outcome.report() : outcome.folds().pooled();
                out.printf("%-60s %9.3f %9.3f %9.3f %9.3f%n", outcome.label(), 100 * outcome.accuracy(),
                        100 * pooled.majorityBaseline(ActionLabel.PRIMARY), 100 * pooled.repeatPreviousBaseline(ActionLabel.PRIMARY),
                        100 * outcome.kickRecall());
            }
        }
    }

    static void printRun(PrintWriter out, ValidationReport report) {
        out.printf("Scenes                   train %d, test %d%n", report.trainScenes(), report.testScenes());
        out.printf("Action accuracy          %.3f %% (%d of %d)%s%n", 100 * report.accuracy(), report.correct(),
                report.testScenes(), baselines(report, ActionLabel.PRIMARY));
        out.printf("Action with direction    %.3f %% (turns count only with the right sign)%n", 100 * report.directionAccuracy());
        out.printf("Body action              %.3f %%%s%n", 100 * report.accuracy(ActionLabel.BODY),
                baselines(report, ActionLabel.BODY));
        if (report.classCounts(ActionLabel.NECK).keySet().equals(Set.of(ActionLabel.NONE))) {
            out.println("Neck action              - (no turn_neck in the test scenes)");
        } else {
            out.printf("Neck action              %.3f %%%s%n", 100 * report.accuracy(ActionLabel.NECK),
                    baselines(report, ActionLabel.NECK));
        }
        out.printf("Body and neck            %.3f %%%s%n", 100 * report.accuracy(ActionLabel.BOTH),
                baselines(report, ActionLabel.BOTH));
        out.printf("  body classes           %s (noop: a turn, dash or kick of 0)%n", classes(report, ActionLabel.BODY));
        out.printf("  neck classes           %s%n", classes(report, ActionLabel.NECK));
        out.printf("Kicks                    %d of %d recalled (%.3f %%), %d predicted, precision %.3f, F1 %.3f%n",
                report.truePositives(ActionType.KICK), report.support(ActionType.KICK),
                100 * nanToZero(report.recall(ActionType.KICK)), report.predictedCount(ActionType.KICK),
                report.precision(ActionType.KICK), report.f1(ActionType.KICK));
        out.printf("Macro F1                 %.4f%n", report.macroF1());
        out.println();
        out.printf("  %-10s %8s %9s %9s %9s %9s%n", "action", "support", "predicted", "precision", "recall", "F1");
        for (ActionType type : report.types()) {
            out.printf("  %-10s %8d %9d %9.4f %9.4f %9.4f%n", type.key(), report.support(type), report.predictedCount(type),
                    report.precision(type), nanToZero(report.recall(type)), report.f1(type));
        }
        out.println();
        out.println("  Confusion (rows: recorded, columns: predicted)");
        StringBuilder header = new StringBuilder(String.format("  %-10s", ""));
        for (ActionType type : report.types()) {
            header.append(String.format(" %9s", type.key()));
        }
        out.println(header);
        for (ActionType truth : report.types()) {
            StringBuilder row = new StringBuilder(String.format("  %-10s", truth.key()));
            for (ActionType predicted : report.types()) {
                row.append(String.format(" %9d", report.confusion(truth, predicted)));
            }
            out.println(row);
        }
        out.println();
        out.println("Parameters where the types agree:");
        out.printf("  turn sign agreement    %s%n", percent(report.turnSignAgreement()));
        out.printf("  turn moment error      %s%n", number(report.turnMomentError()));
        out.printf("  dash power error       %s%n", number(report.dashPowerError()));
        out.printf("  kick power error       %s%n", number(report.kickPowerError()));
        out.printf("  kick direction error   %s%n", number(report.kickDirectionError()));
        out.printf("  dash direction error   %s (body dashes on both sides; a plain dash is 0)%n",
                number(report.dashDirectionError()));
        out.printf("  neck angle error       %s%n", number(report.neckAngleError()));
        boolean warmUp = warmUpOutliers(report);
        out.printf("Decision time            mean %.1f us%s, p50 %.1f us, p99 %.1f us, max %.1f us, all over the same %d"
                        + " decisions%n", report.meanDecisionMicros(), warmUp ? " (warm-up included)" : "",
                report.p50DecisionMicros(), report.p99DecisionMicros(), report.maxDecisionMicros(), report.testScenes());
        if (warmUp) {
            out.println("                         the max is JIT warm-up or a GC pause; p50 and p99 are the steady figures");
        }
        out.printf("Scenes per 100 ms        %d (stored scenes one decision could scan)%n", report.scenesPer100ms());
    }

    /** A mean above the p99, or a max ten times it: a few first or paused decisions, not the matching's speed. */
    static boolean warmUpOutliers(ValidationReport report) {
        double p99 = report.p99DecisionMicros();
        return report.meanDecisionMicros() > p99 || report.maxDecisionMicros() > 10 * p99;
    }

    static void printFolds(PrintWriter out, Folds folds) {
        out.printf("Folds                    %d (each file tested against %s)%n", folds.reports().size(),
                folds.protocol() == Folds.Protocol.NEXT ? "the next one" : "all the others");
        out.printf("  %-28s %10s %10s%n", "figure", "mean", "std");
        for (Map.Entry<String, ToDoubleFunction<ValidationReport>> figure : Folds.figuresWithBaselines().entrySet()) {
            boolean time = figure.getKey().contains("Micros");
            // macro F1 is no rate: printed as the fraction it is, as in the pooled table
            boolean fraction = figure.getKey().equals("macroF1");
            double scale = time || fraction ? 1 : 100;
            out.printf(fraction ? "  %-28s %10.4f %10.4f%s%n" : "  %-28s %10.3f %10.3f%s%n", figure.getKey(),
                    scale * folds.mean(figure.getValue()), scale * folds.std(figure.getValue()),
                    time ? " us" : fraction ? "" : " %");
        }
        out.println();
        out.println("Pooled over the decisions of all folds:");
        printRun(out, folds.pooled());
    }

    /**
     * The two baselines beside an accuracy, flagged when the accuracy does not beat them: a figure
     * below "repeat the previous action" says matching learnt nothing a lookup could not.
     */
    static String baselines(ValidationReport report, ActionLabel label) {
        double majority = report.majorityBaseline(label);
        double previous = report.repeatPreviousBaseline(label);
        if (Double.isNaN(majority) && Double.isNaN(previous)) {
            return "";
        }
        double accuracy = report.accuracy(label);
        String flag = accuracy < Math.max(majority, previous) ? "  << BELOW A BASELINE" : "";
        return String.format("   baselines: majority (%s) %.3f %%, repeat previous %.3f %%%s",
                report.majorityClass(label), 100 * majority, 100 * previous, flag);
    }

    private static String classes(ValidationReport report, ActionLabel label) {
        StringBuilder text = new StringBuilder();
        report.classCounts(label).forEach((name, count) -> text.append(text.length() == 0 ? "" : ", ")
                .append(name).append(' ').append(count));
        return text.length() == 0 ? "none" : text.toString();
    }

    private static double nanToZero(double value) {
        return Double.isNaN(value) ? 0 : value;
    }

    private static String percent(double value) {
        return Double.isNaN(value) ? "-" : String.format("%.3f %%", 100 * value);
    }

    private static String number(double value) {
        return Double.isNaN(value) ? "-" : String.format("%.3f", value);
    }
}
