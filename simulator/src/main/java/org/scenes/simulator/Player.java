package org.scenes.simulator;

import org.scenes.api.Side;

/** One player's body as the server keeps it, with its view mode and command counters. */
final class Player extends MovingObject {
    final String team;
    final Side side;
    final int unum;
    final boolean goalie;
    /** Body direction in degrees, world frame (0 = towards x+, positive = clockwise on screen). */
    double body;
    /** Neck angle relative to the body. */
    double neck;
    double stamina;
    double effort = 1;
    double recovery = 1;
    ViewWidth viewWidth = ViewWidth.NORMAL;
    boolean highQuality = true;
    /** Version 18+ synchronous sees: wider cones, a see every 1, 2 or 3 cycles. */
    boolean synchSee;
    int kicks;
    int dashes;
    int turns;
    int turnNecks;
    int moves;
    int catches;
    int changeViews;
    int says;
    /** Whether a world-changing command was already executed this cycle. */
    boolean acted;

    Player(String team, Side side, int unum, boolean goalie, double stamina) {
        this.team = team;
        this.side = side;
        this.unum = unum;
        this.goalie = goalie;
        this.stamina = stamina;
        this.body = side == Side.LEFT ? 0 : 180;
    }

    double head() {
        return Numbers.normalize(body + neck);
    }

    /**
     * The view cone as a multiple of visible_angle: half, once or twice for narrow, normal and
     * wide; with synchronous sees 2/3, 4/3 and 2 (the cone of 1, 2 or 3 cycles), as on the server.
     */
    double coneFactor() {
        if (!synchSee) {
            return viewWidth.factor;
        }
        return switch (viewWidth) {
            case NARROW -> 2.0 / 3;
            case NORMAL -> 4.0 / 3;
            case WIDE -> 2;
        };
    }

    /** The view widths of {@code change_view}: cone in degrees and see period relative to normal. */
    enum ViewWidth {
        NARROW("narrow", 0.5), NORMAL("normal", 1), WIDE("wide", 2);

        final String word;
        /** The cone's width and the see period, as multiples of visible_angle and send_step. */
        final double factor;

        ViewWidth(String word, double factor) {
            this.word = word;
            this.factor = factor;
        }

        static ViewWidth of(String word) {
            for (ViewWidth width : values()) {
                if (width.word.equals(word)) {
                    return width;
                }
            }
            return null;
        }
    }
}
