package org.scenes.agent.sim;

import org.scenes.scene.Side;

/**
 * Writes what one player senses, as version 9 text: {@code see} (landmarks, ball, players, lines
 * in the view cone; upper-case objects behind within {@code visible_distance}) and
 * {@code sense_body}.
 */
final class Vision {
    /**
     * The server drops a seen player's team with probability rising from 0 at team_far_length to
     * 1 at team_too_far_length, and its uniform number (with the changes and facing that come with
     * it) likewise between unum_far_length and unum_too_far_length; the ball's and flags' changes
     * fade over the same range as the number. This simulator uses the halfway points instead of
     * dice, on the quantised distance as the server does.
     */
    static final double TEAM_VISIBLE = (ServerParams.TEAM_FAR_LENGTH + ServerParams.TEAM_TOO_FAR_LENGTH) / 2;
    static final double UNUM_VISIBLE = (ServerParams.UNUM_FAR_LENGTH + ServerParams.UNUM_TOO_FAR_LENGTH) / 2;
    static final double CHANGES_VISIBLE = UNUM_VISIBLE;

    private final World world;
    private final ServerParams p;
    /** Squared visible distance plus a metre. */
    private final double clearlyFar2;
    /** The view cone of the see being written: half its angle, the cheap test's bound, whether it applies. */
    private double halfAngle;
    private double clearlyOutsideCos2;
    private boolean narrowView;
    private boolean highQuality;
    /** The head's unit vector of the see being written. */
    private double headX;
    private double headY;

    Vision(World world) {
        this.world = world;
        this.p = world.params;
        this.clearlyFar2 = (p.visibleDistance() + 1) * (p.visibleDistance() + 1);
        cone(Player.ViewWidth.NORMAL);
    }

    /** The cone of a view width: visible_angle 90 for normal, half for narrow, twice for wide. */
    private void cone(Player.ViewWidth width) {
        halfAngle = p.visibleAngle() * width.factor / 2;
        double cos = Math.cos(Math.toRadians(halfAngle + 1));
        clearlyOutsideCos2 = cos * cos;
        // The cheap test needs a cone under 178 degrees.
        narrowView = halfAngle + 1 < 90;
    }

    String see(Player self) {
        cone(self.viewWidth);
        highQuality = self.highQuality;
        StringBuilder text = new StringBuilder(2048).append("(see ").append(world.time);
        double head = self.head();
        headX = Math.cos(Math.toRadians(head));
        headY = Math.sin(Math.toRadians(head));
        for (Landmarks.Landmark landmark : Landmarks.ALL) {
            appendObject(text, self, head, landmark.name(), landmark.goal() ? "G" : "F", landmark.x(), landmark.y(),
                    0, 0, p.quantizeStepL(), null);
        }
        Ball ball = world.ball;
        appendObject(text, self, head, "b", "B", ball.x, ball.y, ball.vx, ball.vy, p.quantizeStep(), null);
        for (Player other : world.players) {
            if (other != self) {
                appendObject(text, self, head, null, "P", other.x, other.y, other.vx, other.vy, p.quantizeStep(),
                        other);
            }
        }
        appendLine(text, self, head);
        return text.append(')').toString();
    }

    /**
     * One object, or nothing when it is neither in the view cone nor within
     * {@code visible_distance}; {@code other} is the seen player, null for the rest.
     */
    private void appendObject(StringBuilder text, Player self, double head, String name, String behindName,
                              double x, double y, double vx, double vy, double quantizeStep, Player other) {
        double dx = x - self.x;
        double dy = y - self.y;
        if (narrowView && clearlyUnseen(dx, dy)) {
            return;
        }
        double distance = Math.hypot(dx, dy);
        double direction = Numbers.normalize(Math.toDegrees(Math.atan2(dy, dx)) - head);
        double seenDistance = Numbers.seenDistance(distance, quantizeStep);
        String seenDirection = Numbers.format(Math.rint(direction), 0);
        if (!highQuality) {
            appendLowQuality(text, name, behindName, direction, distance, seenDirection, other);
            return;
        }
        if (Math.abs(direction) >= halfAngle) {
            if (distance <= p.visibleDistance()) {
                text.append(" ((").append(behindName).append(") ").append(Numbers.format(seenDistance, 1))
                        .append(' ').append(seenDirection).append(')');
            }
            return;
        }
        text.append(" ((");
        if (other == null) {
            text.append(name);
        } else if (seenDistance < TEAM_VISIBLE) {
            text.append("p \"").append(other.team).append('"');
            if (seenDistance < UNUM_VISIBLE) {
                text.append(' ').append(other.unum);
                if (other.goalie) {
                    text.append(" goalie");
                }
            }
        } else {
            text.append('p');
        }
        text.append(") ").append(Numbers.format(seenDistance, 1)).append(' ').append(seenDirection);
        if (seenDistance < CHANGES_VISIBLE && distance > 0) {
            // Relative velocity split along and across the line of sight; the radial part is
            // quantised relative to the distance and scaled by the seen distance, as the server does.
            double rvx = vx - self.vx;
            double rvy = vy - self.vy;
            double ex = dx / distance;
            double ey = dy / distance;
            double distanceChange = seenDistance * Numbers.quantize((rvx * ex + rvy * ey) / distance, 0.02);
            double directionChange = Math.toDegrees((rvy * ex - rvx * ey) / distance);
            // An exactly zero direction change stays 0; a tiny negative one quantises to -0.
            directionChange = directionChange == 0 ? 0 : Numbers.quantize(directionChange, 0.1);
            text.append(' ').append(Numbers.formatChange(distanceChange, 4))
                    .append(' ').append(Numbers.formatChange(directionChange, 1));
            if (other != null) {
                text.append(' ').append(Numbers.format(Math.rint(Numbers.normalize(other.body - head)), 0))
                        .append(' ').append(Numbers.format(Math.rint(Numbers.normalize(other.head() - head)), 0));
            }
        }
        text.append(')');
    }

    /**
     * Low view quality: the server sends only the direction of what is in the cone (and of what
     * is behind within visible_distance), without distance or changes; players by team alone.
     */
    private void appendLowQuality(StringBuilder text, String name, String behindName, double direction,
                                  double distance, String seenDirection, Player other) {
        if (Math.abs(direction) >= halfAngle) {
            if (distance <= p.visibleDistance()) {
                text.append(" ((").append(behindName).append(") ").append(seenDirection).append(')');
            }
            return;
        }
        text.append(" ((");
        if (other == null) {
            text.append(name);
        } else if (distance < TEAM_VISIBLE) {
            text.append("p \"").append(other.team).append('"');
        } else {
            text.append('p');
        }
        text.append(") ").append(seenDirection).append(')');
    }

    /**
     * Whether an object is beyond visible_distance and more than a degree outside the view cone:
     * a cheap test without trigonometry that skips most objects of a see (three in four lie
     * outside a 90 degree cone). The margins leave every borderline case to the exact test.
     */
    private boolean clearlyUnseen(double dx, double dy) {
        double squared = dx * dx + dy * dy;
        if (squared <= clearlyFar2) {
            return false;
        }
        double along = dx * headX + dy * headY;
        return along <= 0 || along * along < clearlyOutsideCos2 * squared;
    }

    /**
     * Lines as the server sends them: a line is seen when the view direction points towards it
     * (less than 90 degrees from its outward normal) and meets it within its length; from inside
     * the pitch only the first such line in the order left, right, top, bottom, from outside up
     * to two. Distance along the view direction (landmark quantisation); direction the angle
     * between the view direction and the line, 90 when facing it squarely.
     */
    private void appendLine(StringBuilder text, Player self, double head) {
        boolean inside = Math.abs(self.x) < ServerParams.PITCH_HALF_LENGTH
                && Math.abs(self.y) < ServerParams.PITCH_HALF_WIDTH;
        int wanted = inside ? 1 : 2;
        for (Landmarks.Line line : Landmarks.LINES) {
            if (wanted == 0) {
                return;
            }
            double position = line.vertical() ? self.x : self.y;
            double toLine = line.at() - position;
            // The normal points from the player's side of the line across it.
            double normal = line.vertical() ? (toLine >= 0 ? 0 : 180) : (toLine >= 0 ? 90 : -90);
            double sight = Numbers.normalize(normal - head);
            if (Math.abs(sight) >= 90) {
                continue;
            }
            double radians = Math.toRadians(head);
            double along = line.vertical() ? Math.cos(radians) : Math.sin(radians);
            double distance = toLine / along;
            double across = line.vertical() ? self.y + distance * Math.sin(radians) : self.x + distance * Math.cos(radians);
            double halfLength = line.vertical() ? ServerParams.PITCH_HALF_WIDTH : ServerParams.PITCH_HALF_LENGTH;
            if (Math.abs(across) > halfLength) {
                continue;
            }
            double direction = sight > 0 ? sight - 90 : sight + 90;
            text.append(" ((").append(line.name()).append(") ")
                    .append(Numbers.format(Numbers.seenDistance(Math.abs(distance), p.quantizeStepL()), 1))
                    .append(' ').append(Numbers.format(Math.rint(direction), 0)).append(')');
            wanted--;
        }
    }

    /** The v9 {@code sense_body}, with the extra groups recent servers add in v9 too. */
    String senseBody(Player self) {
        return senseBody(self, 9);
    }

    /**
     * The {@code sense_body} of a protocol version: version 7 ends with the counters, version 8
     * and later add the arm, focus and tackle groups (with constant values here).
     */
    String senseBody(Player self, int version) {
        double speed = self.speed();
        double speedDirection = speed < 1e-9 ? 0
                : Math.rint(Numbers.normalize(Math.toDegrees(Math.atan2(self.vy, self.vx)) - self.head()));
        String head = "(sense_body " + world.time + " (view_mode " + (self.highQuality ? "high " : "low ")
                + self.viewWidth.word + ") (stamina "
                + Numbers.format(Math.rint(self.stamina), 0) + ' ' + Numbers.format(self.effort, 6) + ") (speed "
                + Numbers.format(Numbers.quantize(speed, 0.01), 2) + ' ' + Numbers.format(speedDirection, 0)
                + ") (head_angle " + Numbers.format(Math.rint(self.neck), 0) + ") (kick " + self.kicks
                + ") (dash " + self.dashes + ") (turn " + self.turns + ") (say " + self.says + ") (turn_neck " + self.turnNecks
                + ") (catch " + self.catches + ") (move " + self.moves + ") (change_view " + self.changeViews + ")";
        if (version < 8) {
            return head + ")";
        }
        return head + " (arm (movable 0) (expires 0) (target 0 0) (count 0)) (focus (target none) (count 0))"
                + " (tackle (expires 0) (count 0)))";
    }

    /** The init reply, {@code (init l 3 before_kick_off)}. */
    static String initReply(Player player, String playMode) {
        return "(init " + (player.side == Side.LEFT ? "l" : "r") + ' ' + player.unum + ' ' + playMode + ')';
    }
}
