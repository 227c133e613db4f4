package org.scenes.agent.sim;

import org.scenes.scene.Side;

/**
 * Writes what one player senses, as version 9 text: {@code see} (landmarks, ball, players, lines
 * in the view cone; upper-case objects behind within {@code visible_distance}) and
 * {@code sense_body}.
 */
final class Vision {
    /** Uniform numbers are read up to halfway between far and too far; teams likewise. */
    static final double UNUM_VISIBLE = (ServerParams.UNUM_FAR_LENGTH + ServerParams.UNUM_TOO_FAR_LENGTH) / 2;
    static final double TEAM_VISIBLE = (ServerParams.TEAM_FAR_LENGTH + ServerParams.TEAM_TOO_FAR_LENGTH) / 2;
    /** Distance and direction changes (and a player's facing) are sent up to this distance. */
    static final double CHANGES_VISIBLE = ServerParams.UNUM_FAR_LENGTH;

    private final World world;
    private final ServerParams p;
    private final double halfAngle;

    Vision(World world) {
        this.world = world;
        this.p = world.params;
        this.halfAngle = p.visibleAngle() / 2;
    }

    String see(Player self) {
        StringBuilder text = new StringBuilder(2048).append("(see ").append(world.time);
        double head = self.head();
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
        double distance = Math.hypot(dx, dy);
        double direction = Numbers.normalize(Math.toDegrees(Math.atan2(dy, dx)) - head);
        double seenDistance = Numbers.seenDistance(distance, quantizeStep);
        String seenDirection = Numbers.format(Math.rint(direction), 0);
        if (Math.abs(direction) > halfAngle) {
            if (distance <= p.visibleDistance()) {
                text.append(" ((").append(behindName).append(") ").append(Numbers.format(seenDistance, 1))
                        .append(' ').append(seenDirection).append(')');
            }
            return;
        }
        text.append(" ((");
        if (other == null) {
            text.append(name);
        } else if (distance <= TEAM_VISIBLE) {
            text.append("p \"").append(other.team).append('"');
            if (distance <= UNUM_VISIBLE) {
                text.append(' ').append(other.unum);
            }
        } else {
            text.append('p');
        }
        text.append(") ").append(Numbers.format(seenDistance, 1)).append(' ').append(seenDirection);
        if (distance <= CHANGES_VISIBLE && distance > 0) {
            // Relative velocity split along and across the line of sight, as the server does.
            double rvx = vx - self.vx;
            double rvy = vy - self.vy;
            double ex = dx / distance;
            double ey = dy / distance;
            double distanceChange = (rvx * ex + rvy * ey) * seenDistance / distance;
            double directionChange = Math.toDegrees((rvy * ex - rvx * ey) / distance);
            text.append(' ').append(Numbers.format(Numbers.quantize(distanceChange, 0.02), 2))
                    .append(' ').append(Numbers.format(Numbers.quantize(directionChange, 0.1), 1));
            if (other != null) {
                text.append(' ').append(Numbers.format(Math.rint(Numbers.normalize(other.body - head)), 0))
                        .append(' ').append(Numbers.format(Math.rint(Numbers.normalize(other.head() - head)), 0));
            }
        }
        text.append(')');
    }

    /**
     * The line the view direction meets first: its distance along the view direction and the
     * angle between the line and the view direction (90 when facing it squarely).
     */
    private void appendLine(StringBuilder text, Player self, double head) {
        double radians = Math.toRadians(head);
        double cos = Math.cos(radians);
        double sin = Math.sin(radians);
        Landmarks.Line nearest = null;
        double nearestDistance = Double.POSITIVE_INFINITY;
        for (Landmarks.Line line : Landmarks.LINES) {
            double along = line.vertical() ? cos : sin;
            if (Math.abs(along) < 1e-9) {
                continue;
            }
            double t = (line.at() - (line.vertical() ? self.x : self.y)) / along;
            double across = line.vertical() ? self.y + t * sin : self.x + t * cos;
            double halfExtent = line.vertical() ? ServerParams.PITCH_HALF_WIDTH : ServerParams.PITCH_HALF_LENGTH;
            if (t > 0 && Math.abs(across) <= halfExtent + 1e-9 && t < nearestDistance) {
                nearest = line;
                nearestDistance = t;
            }
        }
        if (nearest == null) {
            return;
        }
        double angle = Numbers.normalize((nearest.vertical() ? 90 : 0) - head);
        if (angle > 90) {
            angle -= 180;
        } else if (angle <= -90) {
            angle += 180;
        }
        text.append(" ((").append(nearest.name()).append(") ")
                .append(Numbers.format(Numbers.seenDistance(nearestDistance, p.quantizeStepL()), 1)).append(' ')
                .append(Numbers.format(Math.rint(angle), 0)).append(')');
    }

    /** The v9 {@code sense_body}, with the extra groups recent servers add in v9 too. */
    String senseBody(Player self) {
        double speed = self.speed();
        double speedDirection = speed < 1e-9 ? 0
                : Math.rint(Numbers.normalize(Math.toDegrees(Math.atan2(self.vy, self.vx)) - self.head()));
        return "(sense_body " + world.time + " (view_mode high normal) (stamina "
                + Numbers.format(Math.rint(self.stamina), 0) + ' ' + Numbers.format(self.effort, 6) + ") (speed "
                + Numbers.format(Numbers.quantize(speed, 0.01), 2) + ' ' + Numbers.format(speedDirection, 0)
                + ") (head_angle " + Numbers.format(Math.rint(self.neck), 0) + ") (kick " + self.kicks
                + ") (dash " + self.dashes + ") (turn " + self.turns + ") (say 0) (turn_neck " + self.turnNecks
                + ") (catch 0) (move " + self.moves + ") (change_view 0)"
                + " (arm (movable 0) (expires 0) (target 0 0) (count 0)) (focus (target none) (count 0))"
                + " (tackle (expires 0) (count 0)))";
    }

    /** The init reply, {@code (init l 3 before_kick_off)}. */
    static String initReply(Player player, String playMode) {
        return "(init " + (player.side == Side.LEFT ? "l" : "r") + ' ' + player.unum + ' ' + playMode + ')';
    }
}
