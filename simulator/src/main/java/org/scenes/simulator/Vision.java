package org.scenes.simulator;

import org.scenes.api.Side;
import org.scenes.internal.vision.Fading;
import org.scenes.internal.vision.SeeWriter;
import org.scenes.internal.vision.VisionParams;

/**
 * Writes what one player senses, as version 9 text: {@code see} (core's {@link SeeWriter}: landmarks,
 * ball, players, lines in the view cone; upper-case objects behind within {@code visible_distance})
 * and {@code sense_body}.
 */
final class Vision {
    private final World world;
    private final SeeWriter writer;

    Vision(World world) {
        this.world = world;
        ServerParams p = world.params;
        // The server drops a seen player's team with probability rising from 0 at team_far_length to
        // 1 at team_too_far_length, and its uniform number (with the changes and facing that come with
        // it) likewise between unum_far_length and unum_too_far_length; the ball's and flags' changes
        // fade over the same range as the number. This simulator uses the halfway points instead of
        // dice, on the quantised distance as the server does.
        VisionParams params = new VisionParams(p.visibleDistance(), p.quantizeStep(), p.quantizeStepL(),
                ServerParams.UNUM_FAR_LENGTH, ServerParams.UNUM_TOO_FAR_LENGTH, ServerParams.TEAM_FAR_LENGTH,
                ServerParams.TEAM_TOO_FAR_LENGTH, ServerParams.UNUM_FAR_LENGTH, ServerParams.UNUM_TOO_FAR_LENGTH,
                ServerParams.UNUM_FAR_LENGTH, ServerParams.UNUM_TOO_FAR_LENGTH);
        this.writer = new SeeWriter(params, Fading.HALFWAY);
    }

    String see(Player self) {
        StringBuilder text = new StringBuilder(2048);
        writer.begin(text, world.time, self.x, self.y, self.vx, self.vy, self.head(),
                world.params.visibleAngle() * self.coneFactor(), self.highQuality);
        writer.landmarks();
        Ball ball = world.ball;
        writer.ball(ball.x, ball.y, ball.vx, ball.vy);
        for (Player other : world.players) {
            if (other != self) {
                writer.player(other.x, other.y, other.vx, other.vy, other.team, other.unum, other.goalie, other.body,
                        other.head());
            }
        }
        writer.lines();
        writer.end();
        return text.toString();
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
