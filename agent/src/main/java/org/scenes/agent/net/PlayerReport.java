package org.scenes.agent.net;

import java.util.Map;

/**
 * How one player's game went, as it stopped.
 *
 * @param unum the uniform number the server gave (0 when it never answered)
 * @param side {@code l} or {@code r}, empty when it never answered
 * @param outcome why it stopped
 * @param reason one line saying what happened (empty for a normal end)
 * @param cycles {@code sense_body} messages received: the server cycles the player lived through
 * @param due cycles in which a body command was due (see {@link LivePlayer})
 * @param missed due cycles whose body command left after the next {@code sense_body} had arrived
 * @param decisions answers of the brain that held a body command: the decision-time sample
 * @param decisionMeanMillis mean decision time over that sample
 * @param decisionP99Millis 99th percentile of the same sample
 * @param decisionMaxMillis the slowest decision
 * @param thinks {@code (think)} messages answered with {@code (done)} (synchronous mode)
 * @param commands datagrams sent after the init
 * @param errors {@code (error ...)} replies by kind
 * @param malformed messages the parser refused, by head; skipped
 * @param brainCounters what the brain counts of itself (guards, silent decisions), by name
 */
public record PlayerReport(String team, int unum, String side, Outcome outcome, String reason, long cycles,
                           long due, long missed, long decisions, double decisionMeanMillis,
                           double decisionP99Millis, double decisionMaxMillis, long thinks, long commands,
                           Map<String, Long> errors, Map<String, Long> malformed, Map<String, Long> brainCounters) {
    public PlayerReport {
        errors = Map.copyOf(errors);
        malformed = Map.copyOf(malformed);
        brainCounters = Map.copyOf(brainCounters);
    }

    /** Why a player stopped. */
    public enum Outcome {
        /** The referee said {@code time_over}. */
        GAME_OVER,
        /** Asked to stop (Ctrl-C, SIGTERM, the caller). */
        STOPPED,
        /** No answer to the init in time, or the server refused the player. */
        NO_SERVER,
        /** The server went silent or away during the game. */
        SERVER_LOST,
        /** The player itself failed (its brain threw, a write failed). */
        FAILED;

        /** Whether the player did what it was started for. */
        public boolean ok() {
            return this == GAME_OVER || this == STOPPED;
        }
    }
}
