package org.scenes.internal.convert;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.scenes.api.Observer;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.PlayerState;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.See;
import org.scenes.internal.protocol.SenseBody;
import org.scenes.internal.protocol.VisualObject;
import org.scenes.internal.vision.SeeWriter;
import org.scenes.internal.vision.VisionNumbers;

/**
 * Rebuilds what a player got and sent, message by message, from the game log's shows: its
 * {@code init} answers, the {@code see} the server would have sent (by {@link SeeWriter}, with the
 * vision model), its {@code sense_body}, the referee's calls it heard, and its own commands; each
 * line goes to the player's {@link SceneConverter.Feed}. One per worker: it holds a parser.
 */
final class PerceptWriter {
    private final Path gameLog;
    private final GameParameters parameters;
    private final SceneConverter converter;
    /** This writer's own: a parser serves one thread. */
    private final MessageParser parser = new MessageParser();

    PerceptWriter(Path gameLog, GameParameters parameters, SceneConverter converter) {
        this.gameLog = gameLog;
        this.parameters = parameters;
        this.converter = converter;
    }

    /** Whether the scenes carry world models, which read the player's state and the referee's calls. */
    boolean world() {
        return converter.world();
    }

    /** Opens the player's feed at its first show with what the server answered its init. */
    void start(RebuiltPlayer player, GameFrame frame) throws IOException {
        player.feed = converter.feed(Path.of(gameLog + "#" + player.key), player.sink);
        Observer o = player.observer;
        line(player, "(init " + o.team() + " (version " + Math.max(player.version, 3) + ")"
                + (player.goalie ? " (goalie)" : "") + ")");
        line(player, "(init " + o.side().letter() + ' ' + o.uniformNumber() + ' ' + frame.playMode() + ")");
        player.heardMode = frame.playMode();
        if (player.synchSee) {
            line(player, "(ok synch_see)");
        }
    }

    /** A message the player sent; {@code synch_see} becomes the server's answer. */
    void deliver(RebuiltPlayer player, String message) throws IOException {
        if (message.startsWith("(synch_see)")) {
            if (!player.synchSee) {
                player.synchSee = true;
                line(player, "(ok synch_see)");
            }
            return;
        }
        if (BodyCommands.first(parser, message) != null) {
            player.sentBody = true;
        }
        line(player, message);
    }

    /** The see the server sends the player of what the show holds, in its view mode and heterogeneous type. */
    void see(RebuiltPlayer player, PlayerState self, GameFrame frame) throws IOException {
        if (player.writer == null || player.type != self.type()) {
            player.type = self.type();
            player.writer = new SeeWriter(parameters.vision(self.type(), player.version), player.fading);
        }
        SeeWriter writer = player.writer;
        // the see as the parser would read it, not as text to read back: that round trip took a third of a conversion
        List<VisualObject> objects = new ArrayList<>(48);
        double head = VisionNumbers.normalize(self.body() + self.neck());
        writer.begin(objects, self.x(), self.y(), self.vx(), self.vy(), head, self.viewWidth(),
                self.viewQuality() == 'h');
        writer.landmarks();
        GameFrame.BallState ball = frame.ball();
        writer.ball(ball.x(), ball.y(), ball.vx(), ball.vy());
        for (PlayerState other : frame.players()) {
            if (other == self || other.state() == 0) {
                continue;
            }
            String team = other.side() == Side.LEFT ? frame.leftTeam() : frame.rightTeam();
            writer.player(other.x(), other.y(), other.vx(), other.vy(), team, other.unum(),
                    (other.state() & PlayerState.GOALIE) != 0, other.body(),
                    VisionNumbers.normalize(other.body() + other.neck()));
        }
        writer.lines();
        writer.end();
        player.feed.line(new See(frame.time(), objects, List.of()));
    }

    /** The bare {@code sense_body} of a cycle, when no world model reads its fields. */
    void senseBody(RebuiltPlayer player, int time) throws IOException {
        line(player, "(sense_body " + time + ")");
    }

    /**
     * The player's {@code sense_body} as the server writes it (version 7's fields, which the
     * world model reads): stamina, speed relative to the head, neck angle, command counts; given
     * as the parser reads the server's text (numbers rounded as it writes them), not as text to read back.
     */
    void senseBody(RebuiltPlayer player, PlayerState self, int time) throws IOException {
        player.feed.line(senseBodyOf(self, time));
    }

    /** The {@code sense_body} of {@link #senseBody}: each number as the parser reads the server's text of it. */
    static SenseBody senseBodyOf(PlayerState self, int time) {
        PlayerState.Counts c = self.counts();
        return new SenseBody(time, self.viewQuality() == 'h' ? "high" : "low", viewWidth(self),
                VisionNumbers.asRead(Math.rint(self.stamina()), 0), VisionNumbers.asRead(self.effort(), 6),
                VisionNumbers.asRead(self.capacity(), 0), VisionNumbers.asRead(VisionNumbers.quantize(speed(self), 0.01), 2),
                VisionNumbers.asRead(speedDirection(self), 0), VisionNumbers.asRead(Math.rint(self.neck()), 0),
                new SenseBody.Counts(c.kick(), c.dash(), c.turn(), c.say(), c.turnNeck(), c.catches(), c.move(),
                        c.changeView(), -1), Map.of(), List.of());
    }

    private static String viewWidth(PlayerState self) {
        return self.viewWidth() <= 60 ? "narrow" : self.viewWidth() >= 180 ? "wide" : "normal";
    }

    private static double speed(PlayerState self) {
        return Math.hypot(self.vx(), self.vy());
    }

    /** The direction of the player's velocity relative to its head, whole degrees (0 when still). */
    private static double speedDirection(PlayerState self) {
        double head = self.body() + self.neck();
        return speed(self) < 1e-9 ? 0
                : Math.rint(VisionNumbers.normalize(Math.toDegrees(Math.atan2(self.vy(), self.vx())) - head));
    }

    /** The referee's call when the play mode changed since the player last heard ({@code goal_l_2} for goals). */
    void referee(RebuiltPlayer player, GameFrame frame) throws IOException {
        String mode = frame.playMode();
        if (mode.equals(player.heardMode)) {
            return;
        }
        player.heardMode = mode;
        String word = mode.equals("goal_l") ? "goal_l_" + frame.scoreLeft()
                : mode.equals("goal_r") ? "goal_r_" + frame.scoreRight() : mode;
        line(player, "(hear " + frame.time() + " referee " + word + ")");
    }

    /**
     * One line to the player's feed, as UTF-8 bytes: the text's own bytes for ASCII (a String
     * of one-byte characters is copied whole, not char by char).
     */
    private void line(RebuiltPlayer player, CharSequence message) throws IOException {
        byte[] encoded = message.toString().getBytes(StandardCharsets.UTF_8);
        player.feed.line(encoded, 0, encoded.length);
    }
}
