package org.scenes.internal.inference;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumMap;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.scenes.internal.gamelog.CommandLogReader;
import org.scenes.internal.protocol.CommandType;
import org.scenes.internal.protocol.Message;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.PlayerCommand;
import org.scenes.internal.protocol.ProtocolException;

/**
 * The commands inferred from a game log alone set against its command log, per body command the
 * counters say was executed: whether the type agrees with the command log's first body command of
 * that player and step, and how far the arguments are from those sent (clamped to the server's
 * ranges and a dash's power to the stamina left: the server executes those values).
 */
public final class CommandCheck {
    /**
     * The comparison of one game (or several, {@link #add}ed).
     *
     * @param executed body commands the counters say were executed
     * @param agreed   of them, those whose type the command log gives in the same step
     */
    public record Result(long executed, long agreed, Map<CommandType, Long> byType, double[] turnErrors,
                         double[] dashPowerErrors, double[] dashDirectionErrors, double[] kickDirectionErrors,
                         double[] kickPowerErrors, double[] neckErrors, double[] kickBounds, List<String> warnings) {
        public double agreement() {
            return executed == 0 ? Double.NaN : (double) agreed / executed;
        }

        public double turnMedian() {
            return quantile(turnErrors, 0.5);
        }

        /** Share of dashes whose power is within 5 % of the one sent. */
        public double dashPowerWithin5() {
            return share(dashPowerErrors, 0.05);
        }

        /** Share of kicks whose direction is within 5 degrees of the one sent. */
        public double kickDirectionWithin5() {
            return share(kickDirectionErrors, 5);
        }

        public Result add(Result other) {
            Map<CommandType, Long> types = new EnumMap<>(CommandType.class);
            types.putAll(byType);
            other.byType.forEach((k, v) -> types.merge(k, v, Long::sum));
            List<String> all = new ArrayList<>(warnings);
            all.addAll(other.warnings);
            return new Result(executed + other.executed, agreed + other.agreed, types, join(turnErrors, other.turnErrors),
                    join(dashPowerErrors, other.dashPowerErrors), join(dashDirectionErrors, other.dashDirectionErrors),
                    join(kickDirectionErrors, other.kickDirectionErrors), join(kickPowerErrors, other.kickPowerErrors),
                    join(neckErrors, other.neckErrors), join(kickBounds, other.kickBounds), all);
        }

        /** The figures as a table, one row per measure. */
        public String table() {
            StringBuilder out = new StringBuilder();
            out.append(String.format(Locale.ROOT, "%-40s %s%n", "Body commands executed", executed + " " + byType));
            out.append(String.format(Locale.ROOT, "%-40s %.2f %% (%d of %d)%n", "Type agrees with the command log",
                    100 * agreement(), agreed, executed));
            out.append(String.format(Locale.ROOT, "%-40s %.3f deg median, %.2f deg p90 (%d turns)%n", "Turn moment error",
                    turnMedian(), quantile(turnErrors, 0.9), turnErrors.length));
            out.append(String.format(Locale.ROOT, "%-40s %.2f %% (%d dashes)%n", "Dash power within 5 %",
                    100 * dashPowerWithin5(), dashPowerErrors.length));
            out.append(String.format(Locale.ROOT, "%-40s %.2f %% within 10 deg, %.2f deg median%n", "Dash direction",
                    100 * share(dashDirectionErrors, 10), quantile(dashDirectionErrors, 0.5)));
            out.append(String.format(Locale.ROOT, "%-40s %.2f %% (%d kicks), %.2f deg median%n", "Kick direction within 5 deg",
                    100 * kickDirectionWithin5(), kickDirectionErrors.length, quantile(kickDirectionErrors, 0.5)));
            long tight = 0;
            long tightWithin = 0;
            long withinBound = 0;
            for (int i = 0; i < kickDirectionErrors.length; i++) {
                withinBound += kickDirectionErrors[i] <= kickBounds[i] ? 1 : 0;
                if (kickBounds[i] <= 5) {
                    tight++;
                    tightWithin += kickDirectionErrors[i] <= 5 ? 1 : 0;
                }
            }
            out.append(String.format(Locale.ROOT, "%-40s %.2f %% within their bound; of the %d bound to 5 deg,"
                    + " %.2f %% within 5 deg%n", "Kick direction and its bound", 100.0 * withinBound
                    / Math.max(1, kickBounds.length), tight, 100.0 * tightWithin / Math.max(1, tight)));
            out.append(String.format(Locale.ROOT, "%-40s %.2f %%%n", "Kick power within 10 %",
                    100 * share(kickPowerErrors, 0.10)));
            out.append(String.format(Locale.ROOT, "%-40s %.2f %% within 1 deg (%d)%n", "Neck turn (turn_neck)",
                    100 * share(neckErrors, 1), neckErrors.length));
            return out.toString();
        }
    }

    private CommandCheck() {
    }

    /** Infers the commands of {@code gameLog} and sets them against {@code commandLog}. */
    public static Result check(Path gameLog, Path commandLog) throws IOException {
        Map<String, StringBuilder> sent = new HashMap<>();
        try (CommandLogReader reader = CommandLogReader.open(commandLog)) {
            CommandLogReader.Entry entry;
            while ((entry = reader.next()) != null) {
                if (!entry.referee()) {
                    sent.computeIfAbsent(key(entry.time(), entry.stoppage(), entry.team(), entry.unum()),
                            k -> new StringBuilder()).append(entry.text());
                }
            }
        }
        Comparison comparison = new Comparison();
        List<String> warnings = InferredCommandLog.infer(gameLog, step -> {
            StringBuilder text = sent.get(key(step.time(), step.stoppage(), step.team(), step.unum()));
            comparison.compare(step.step(), text == null ? "" : text.toString(), step.staminaLeft());
        });
        return comparison.result(warnings);
    }

    private static String key(int time, int stoppage, String team, int unum) {
        return time + "," + stoppage + " " + team + "_" + unum;
    }

    private static final class Comparison {
        final MessageParser parser = new MessageParser();
        long executed;
        long agreed;
        final Map<CommandType, Long> byType = new EnumMap<>(CommandType.class);
        final Errors turn = new Errors();
        final Errors dashPower = new Errors();
        final Errors dashDirection = new Errors();
        final Errors kickDirection = new Errors();
        final Errors kickPower = new Errors();
        final Errors neck = new Errors();
        final Errors kickBound = new Errors();

        void compare(CommandInference.Step step, String sent, double staminaLeft) {
            List<PlayerCommand> commands = commands(sent);
            CommandInference.Command neckTurn = find(step.commands(), CommandType.TURN_NECK);
            PlayerCommand sentNeck = first(commands, CommandType.TURN_NECK);
            if (neckTurn != null && sentNeck != null && Double.isFinite(neckTurn.firstBound())) {
                neck.add(Math.abs(neckTurn.first() - sentNeck.first()));
            }
            CommandType body = step.body();
            if (body == null) {
                return;
            }
            executed++;
            byType.merge(body, 1L, Long::sum);
            PlayerCommand truth = null;
            for (PlayerCommand command : commands) {
                if (command.type().body()) {
                    truth = command;
                    break;
                }
            }
            if (truth == null || truth.type() != body) {
                return;
            }
            agreed++;
            CommandInference.Command inferred = find(step.commands(), body);
            switch (body) {
                case TURN -> turn.add(Math.abs(inferred.first() - clamp(truth.first(), -180, 180)));
                case DASH -> {
                    // the power executed: a tired player dashes with the stamina it has
                    double power = Math.min(clamp(truth.first(), 0, 100), Math.max(0, staminaLeft));
                    dashPower.add(Math.abs(inferred.first() - power) / Math.max(power, 1));
                    double direction = Double.isNaN(truth.second()) ? 0 : truth.second();
                    dashDirection.add(Math.abs(CommandInference.normalize(inferred.second() - direction)));
                }
                case KICK -> {
                    double direction = clamp(truth.second(), -180, 180);
                    kickDirection.add(Math.abs(CommandInference.normalize(inferred.second() - direction)));
                    kickBound.add(inferred.secondBound());
                    double power = clamp(truth.first(), 0, 100);
                    kickPower.add(Math.abs(inferred.first() - power) / Math.max(power, 1));
                }
                default -> {
                }
            }
        }

        List<PlayerCommand> commands(String sent) {
            List<PlayerCommand> commands = new ArrayList<>(4);
            if (sent.isEmpty()) {
                return commands;
            }
            byte[] bytes = sent.getBytes(StandardCharsets.UTF_8);
            List<Message> messages = new ArrayList<>(6);
            try {
                parser.parseAll(bytes, 0, bytes.length, messages::add);
            } catch (ProtocolException malformed) {
                // the commands before a malformed one were executed
            }
            for (Message message : messages) {
                if (message instanceof PlayerCommand command && command.wellFormed()) {
                    commands.add(command);
                }
            }
            return commands;
        }

        static PlayerCommand first(List<PlayerCommand> commands, CommandType type) {
            for (PlayerCommand command : commands) {
                if (command.type() == type) {
                    return command;
                }
            }
            return null;
        }

        static CommandInference.Command find(List<CommandInference.Command> commands, CommandType type) {
            for (CommandInference.Command command : commands) {
                if (command.type() == type) {
                    return command;
                }
            }
            return null;
        }

        Result result(List<String> warnings) {
            return new Result(executed, agreed, byType, turn.values(), dashPower.values(), dashDirection.values(),
                    kickDirection.values(), kickPower.values(), neck.values(), kickBound.values(), warnings);
        }
    }

    /** A growing list of errors. */
    private static final class Errors {
        double[] values = new double[1024];
        int size;

        void add(double value) {
            if (size == values.length) {
                values = Arrays.copyOf(values, size * 2);
            }
            values[size++] = value;
        }

        double[] values() {
            return Arrays.copyOf(values, size);
        }
    }

    private static double clamp(double value, double low, double high) {
        return Math.max(low, Math.min(high, value));
    }

    private static double[] join(double[] a, double[] b) {
        double[] all = Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, all, a.length, b.length);
        return all;
    }

    static double quantile(double[] values, double q) {
        if (values.length == 0) {
            return Double.NaN;
        }
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        return sorted[(int) Math.min(sorted.length - 1, Math.floor(q * sorted.length))];
    }

    static double share(double[] values, double limit) {
        if (values.length == 0) {
            return Double.NaN;
        }
        long within = Arrays.stream(values).filter(v -> v <= limit + 1e-9).count();
        return (double) within / values.length;
    }
}
