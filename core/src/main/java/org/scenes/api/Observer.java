package org.scenes.api;

/**
 * The player whose view a scene holds.
 *
 * @param team team name as sent in {@code init}; empty when unknown
 * @param side the side from the server's {@code init} reply; null when unknown
 * @param uniformNumber uniform number from the {@code init} reply; 0 when unknown
 */
public record Observer(String team, Side side, int uniformNumber) {
    /** A player of unknown team, side and number (a log without {@code init}). */
    public static final Observer UNKNOWN = new Observer("", null, 0);

    /**
     * A null team becomes empty.
     *
     * @param team team name, null or empty when unknown
     * @param side the side, null when unknown
     * @param uniformNumber uniform number, 0 when unknown
     */
    public Observer {
        team = team == null ? "" : team;
    }

    /**
     * "Carleton 3 (l)" style label for reports.
     *
     * @return team, number when known and side letter when known
     */
    public String label() {
        StringBuilder label = new StringBuilder(team.isEmpty() ? "?" : team);
        if (uniformNumber > 0) {
            label.append(' ').append(uniformNumber);
        }
        if (side != null) {
            label.append(" (").append(side.letter()).append(')');
        }
        return label.toString();
    }
}
