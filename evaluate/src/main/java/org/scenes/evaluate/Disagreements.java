package org.scenes.evaluate;

import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.math.BigDecimal;
import java.math.RoundingMode;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import org.scenes.internal.files.AtomicOutput;
import org.scenes.internal.protocol.PlayerCommand;

/**
 * Where the imitator and its shadow teacher part, see by see: a CSV file with one row per see of
 * the game clock running on which they did not agree ({@link GameFigures#agree}: another body
 * command, or a turn the other way round) or only one of them answered. Columns: {@code round}
 * (0 without DAgger), {@code seed}, {@code unum}, {@code cycle} (the see's game time),
 * {@code imitator} and {@code shadow}, each the first body command sent on that see, empty for none.
 */
public final class Disagreements {
    private Disagreements() {
    }

    /** Writes the imitator's games of each round (index = round) to {@code file}, atomically; returns the rows written. */
    public static long write(Path file, List<Evaluation.Results> rounds) throws IOException {
        long rows = 0;
        try (AtomicOutput output = AtomicOutput.create(file)) {
            Writer out = new OutputStreamWriter(output.stream(), StandardCharsets.UTF_8);
            out.write("round,seed,unum,cycle,imitator,shadow\n");
            for (int round = 0; round < rounds.size(); round++) {
                for (PlayedGame game : rounds.get(round).imitator()) {
                    for (PlayerTrace trace : game.traces()) {
                        for (PlayerTrace.Decision decision : trace.decisions()) {
                            if (parted(decision)) {
                                out.write(round + "," + game.seed() + "," + trace.unum() + "," + decision.time() + ","
                                        + text(decision.driver()) + "," + text(decision.shadow()) + "\n");
                                rows++;
                            }
                        }
                    }
                }
            }
            out.flush();
            output.commit();
        }
        return rows;
    }

    /** Whether imitator and shadow part on a see of the running clock. */
    static boolean parted(PlayerTrace.Decision decision) {
        if (decision.paused() || (decision.driver() == null && decision.shadow() == null)) {
            return false;
        }
        return decision.driver() == null || decision.shadow() == null
                || !GameFigures.agree(decision.driver(), decision.shadow());
    }

    /** A body command as protocol text ({@code (dash 100)}, {@code (kick 100 -30)}), empty for none. */
    private static String text(PlayerCommand command) {
        if (command == null) {
            return "";
        }
        StringBuilder text = new StringBuilder("(").append(command.type().key());
        for (double argument : new double[] {command.first(), command.second()}) {
            if (!Double.isNaN(argument)) {
                text.append(' ').append(BigDecimal.valueOf(argument).setScale(3, RoundingMode.HALF_EVEN)
                        .stripTrailingZeros().toPlainString());
            }
        }
        return text.append(')').toString();
    }
}
