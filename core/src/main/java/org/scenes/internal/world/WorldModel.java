package org.scenes.internal.world;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.scenes.api.Action;
import org.scenes.api.ActionType;
import org.scenes.api.ObjectKind;
import org.scenes.api.Relation;
import org.scenes.api.Side;
import org.scenes.api.World;
import org.scenes.internal.protocol.CommandType;
import org.scenes.internal.protocol.Hear;
import org.scenes.internal.protocol.InitReply;
import org.scenes.internal.protocol.InitRequest;
import org.scenes.internal.protocol.Message;
import org.scenes.internal.protocol.PlayerCommand;
import org.scenes.internal.protocol.Score;
import org.scenes.internal.protocol.See;
import org.scenes.internal.protocol.SenseBody;
import org.scenes.internal.protocol.VisualObject;

/**
 * One player's world model, fed its messages in the order it got and sent them ({@link #accept}),
 * read as a {@link World} in its own frame ({@link #snapshot}). Held in the server's frame:
 *
 * <ul>
 *   <li>a {@code see} places the player ({@link Localisation}), then the ball and the players it
 *   shows; the ball's velocity from its distance and direction changes when sent, else from its
 *   last two positions;</li>
 *   <li>a {@code sense_body} of a later cycle moves what is not seen: the player by the velocity it
 *   reports (its neck and stamina too), its body by an executed {@code turn}, the ball by its
 *   velocity with the ball's decay; players stay where last seen, growing older;</li>
 *   <li>a {@code see} without the ball where the model holds it (within the distance every see
 *   covers, or straight ahead) forgets the ball: it is not there, and a player acting on a ball
 *   it would kick forever is worse off than one that knows it has lost it;</li>
 *   <li>the referee's calls give the play mode and the score ({@code goal_l_2}: the left team has
 *   2); a kick-off places the ball on the centre spot, as the rules do.</li>
 * </ul>
 *
 * Motion uses the default server's constants (player decay 0.4, ball decay 0.94, inertia moment 5):
 * what only carries a value between sees. Not thread-safe.
 */
public final class WorldModel {
    /** How far from the centre the server lets a player go: half the pitch plus the 5 m margin. */
    static final double MAX_X = 57.5;
    static final double MAX_Y = 39;
    /** Cycles a player seen with its team and number is remembered. */
    static final int PLAYER_MEMORY = 30;
    /**
     * How much nearer than the visible distance, and within how many degrees of the head, a ball
     * the model holds must lie for a see without it to forget it: room for the model's error.
     */
    static final double BALL_MISSING_MARGIN = 0.5;
    static final double BALL_MISSING_CONE = ServerDefaults.NARROWEST_HALF_VIEW - 2.5;

    private String team = "";
    private Side side;
    private int time = -1;

    private double x = Double.NaN;
    private double y = Double.NaN;
    /** The head's direction (body + neck), server frame. */
    private double head = Double.NaN;
    private double neck = 0;
    private double vx = Double.NaN;
    private double vy = Double.NaN;
    private double speed;
    private double stamina = Double.NaN;
    private double effort = Double.NaN;
    private int locatedAt = -1;

    private double ballX = Double.NaN;
    private double ballY = Double.NaN;
    private double ballVx = Double.NaN;
    private double ballVy = Double.NaN;
    private int ballSeenAt = -1;
    /** Where the ball was last seen (the model's position moves on between sees). */
    private double seenBallX;
    private double seenBallY;

    /** Players seen with team and number, by relation and number; the rest of the latest see. */
    private final Map<Long, Seen> named = new LinkedHashMap<>();
    private final List<Seen> unnamed = new ArrayList<>();

    private String playMode = "";
    private int scoreLeft;
    private int scoreRight;

    /** The last turn sent, and the turn count of the last sense_body. */
    private double turnMoment = Double.NaN;
    private int turns = -1;

    private record Seen(Relation relation, int unum, double x, double y, int time) {
    }

    /** A model learning the player's team from its {@code init}, as a log shows it. */
    public WorldModel() {
    }

    /** A model of a player of {@code team} (a live player, whose own {@code init} it does not see). */
    public WorldModel(String team) {
        this.team = team;
    }

    /** Takes in one message the player got or sent. */
    public void accept(Message message) {
        if (message instanceof See see) {
            see(see);
        } else if (message instanceof SenseBody body) {
            senseBody(body);
        } else if (message instanceof Hear hear) {
            if (hear.speaker() == Hear.Speaker.REFEREE) {
                referee(hear.text(), hear.time());
            }
        } else if (message instanceof PlayerCommand command) {
            if (command.type() == CommandType.TURN && command.wellFormed()) {
                turnMoment = command.first();
            }
        } else if (message instanceof InitRequest init) {
            team = init.team();
        } else if (message instanceof InitReply reply) {
            side = reply.side() != null ? reply.side() : side;
            if (reply.playMode() != null) {
                referee(reply.playMode(), Math.max(0, time));
            }
        } else if (message instanceof Score score && side != null) {
            scoreLeft = side == Side.LEFT ? score.our() : score.their();
            scoreRight = side == Side.LEFT ? score.their() : score.our();
        }
    }

    /** Takes in a command the player sent, as an action (a live player's own decision). */
    public void sent(Action action) {
        if (action != null && action.type() == ActionType.TURN) {
            turnMoment = action.first();
        }
    }

    private void senseBody(SenseBody body) {
        int elapsed = time < 0 ? 0 : body.time() - time;
        time = Math.max(time, body.time());
        if (!Double.isNaN(body.stamina())) {
            stamina = body.stamina();
            effort = body.effort();
        }
        double newNeck = Double.isNaN(body.headAngle()) ? neck : body.headAngle();
        if (!Double.isNaN(head)) {
            double bodyDirection = head - neck;
            int counted = body.counts().turn();
            if (counted >= 0 && turns >= 0 && counted > turns && !Double.isNaN(turnMoment)) {
                // the server turns by moment / (1 + inertia * speed), the speed before the step
                bodyDirection += Math.max(-180, Math.min(180, turnMoment)) / (1 + ServerDefaults.INERTIA_MOMENT * speed);
            }
            head = Localisation.normalize(bodyDirection + newNeck);
        }
        turns = body.counts().turn();
        neck = newNeck;
        if (!Double.isNaN(body.speed()) && !Double.isNaN(head)) {
            double direction = Math.toRadians(head + (Double.isNaN(body.speedDirection()) ? 0 : body.speedDirection()));
            speed = body.speed();
            vx = speed * Math.cos(direction);
            vy = speed * Math.sin(direction);
        }
        if (elapsed > 0) {
            if (!Double.isNaN(x) && !Double.isNaN(vx)) {
                // the reported velocity is the step's movement after decay; the server keeps
                // players within the pitch's margin (5 m beyond its lines)
                x = Math.max(-MAX_X, Math.min(MAX_X, x + vx / ServerDefaults.PLAYER_DECAY));
                y = Math.max(-MAX_Y, Math.min(MAX_Y, y + vy / ServerDefaults.PLAYER_DECAY));
            }
            for (int i = 0; i < elapsed && !Double.isNaN(ballVx); i++) {
                ballX += ballVx;
                ballY += ballVy;
                ballVx *= ServerDefaults.BALL_DECAY;
                ballVy *= ServerDefaults.BALL_DECAY;
            }
        }
    }

    private void see(See see) {
        time = Math.max(time, see.time());
        Localisation.Pose pose = Localisation.locate(see, head);
        if (pose != null) {
            x = pose.x();
            y = pose.y();
            head = pose.head();
            locatedAt = see.time();
        }
        if (Double.isNaN(x) || Double.isNaN(head)) {
            return;
        }
        unnamed.clear();
        boolean ballSeen = false;
        for (VisualObject object : see.objects()) {
            ballSeen |= object.kind() == ObjectKind.BALL;
            if (Double.isNaN(object.distance()) || Double.isNaN(object.direction())) {
                continue;
            }
            double a = Math.toRadians(head + object.direction());
            double ox = x + object.distance() * Math.cos(a);
            double oy = y + object.distance() * Math.sin(a);
            if (object.kind() == ObjectKind.BALL) {
                ball(object, ox, oy, a, see.time());
            } else if (object.kind() == ObjectKind.PLAYER) {
                Relation relation = object.behind() || object.team().isEmpty() || team.isEmpty() ? Relation.UNKNOWN
                        : object.team().equals(team) ? Relation.TEAMMATE : Relation.OPPONENT;
                Seen seen = new Seen(relation, object.uniformNumber(), ox, oy, see.time());
                if (relation != Relation.UNKNOWN && object.uniformNumber() > 0) {
                    named.put(namedKey(relation, object.uniformNumber()), seen);
                } else {
                    unnamed.add(seen);
                }
            }
        }
        named.values().removeIf(seen -> see.time() - seen.time() > PLAYER_MEMORY);
        if (!ballSeen && !Double.isNaN(ballX) && ballWouldBeSeen()) {
            ballX = Double.NaN;
            ballY = Double.NaN;
            ballVx = Double.NaN;
            ballVy = Double.NaN;
            ballSeenAt = -1;
        }
    }

    /** Whether the ball, where the model holds it, lies where every see would show it. */
    private boolean ballWouldBeSeen() {
        double dx = ballX - x;
        double dy = ballY - y;
        if (Math.hypot(dx, dy) < ServerDefaults.VISIBLE_DISTANCE - BALL_MISSING_MARGIN) {
            return true;
        }
        return Math.abs(Localisation.normalize(Math.toDegrees(Math.atan2(dy, dx)) - head)) < BALL_MISSING_CONE;
    }

    private void ball(VisualObject object, double bx, double by, double direction, int seenAt) {
        if (!Double.isNaN(object.distanceChange()) && !Double.isNaN(object.directionChange()) && !Double.isNaN(vx)) {
            // relative velocity: the distance change along the line of sight, the direction change across it
            double ex = Math.cos(direction);
            double ey = Math.sin(direction);
            double across = Math.toRadians(object.directionChange()) * object.distance();
            ballVx = vx + object.distanceChange() * ex - across * ey;
            ballVy = vy + object.distanceChange() * ey + across * ex;
        } else if (ballSeenAt >= 0 && seenAt > ballSeenAt && seenAt - ballSeenAt <= 3) {
            ballVx = (bx - seenBallX) / (seenAt - ballSeenAt);
            ballVy = (by - seenBallY) / (seenAt - ballSeenAt);
        } else if (Double.isNaN(ballVx) || ballSeenAt < 0) {
            ballVx = 0;
            ballVy = 0;
        }
        ballX = bx;
        ballY = by;
        seenBallX = bx;
        seenBallY = by;
        ballSeenAt = seenAt;
    }

    private void referee(String word, int heardAt) {
        if (word.startsWith("yellow_card") || word.startsWith("red_card")) {
            return; // a card, not a play mode
        }
        if (word.equals("before_kick_off") || word.equals("kick_off_l") || word.equals("kick_off_r")) {
            placeBall(0, 0, heardAt);
        }
        if (word.startsWith("goal_l_") || word.startsWith("goal_r_")) {
            try {
                int goals = Integer.parseInt(word.substring(7));
                if (word.charAt(5) == 'l') {
                    scoreLeft = goals;
                } else {
                    scoreRight = goals;
                }
            } catch (NumberFormatException e) {
                // not a goal count: keep the word as the play mode
            }
            playMode = word.substring(0, 6);
            return;
        }
        playMode = word;
    }

    /** The ball where the referee put it, at rest: known as if seen there. */
    private void placeBall(double bx, double by, int at) {
        ballX = bx;
        ballY = by;
        ballVx = 0;
        ballVy = 0;
        seenBallX = bx;
        seenBallY = by;
        ballSeenAt = at;
    }

    /** A seen player's key in {@link #named}: its relation and number (no text made per player seen). */
    private static long namedKey(Relation relation, int unum) {
        return (long) relation.ordinal() << 32 | (unum & 0xffffffffL);
    }

    /** The model at {@code cycle} in the player's own frame (the right team's turned by 180 degrees). */
    public World snapshot(int cycle) {
        boolean mirrored = side == Side.RIGHT;
        double sign = mirrored ? -1 : 1;
        double bodyDirection = Double.isNaN(head) ? Double.NaN
                : Localisation.normalize(head - neck + (mirrored ? 180 : 0));
        // an array made into an immutable list once: World keeps such a list as it is
        World.Player[] seenPlayers = new World.Player[named.size() + unnamed.size()];
        int count = 0;
        for (Seen seen : unnamed) {
            seenPlayers[count++] = new World.Player(seen.relation(), seen.unum(), round(sign * seen.x()),
                    round(sign * seen.y()), Math.max(0, cycle - seen.time()));
        }
        for (Seen seen : named.values()) {
            seenPlayers[count++] = new World.Player(seen.relation(), seen.unum(), round(sign * seen.x()),
                    round(sign * seen.y()), Math.max(0, cycle - seen.time()));
        }
        List<World.Player> players = List.of(seenPlayers);
        int own = side == Side.RIGHT ? scoreRight : scoreLeft;
        int opponent = side == Side.RIGHT ? scoreLeft : scoreRight;
        return new World(round(sign * x), round(sign * y), round(bodyDirection), neck, round(sign * vx),
                round(sign * vy), stamina, effort, locatedAt < 0 ? -1 : Math.max(0, cycle - locatedAt),
                round(sign * ballX), round(sign * ballY), round(sign * ballVx), round(sign * ballVy),
                ballSeenAt < 0 ? -1 : Math.max(0, cycle - ballSeenAt), players, playMode, own, opponent);
    }

    /** To the centimetre (or hundredth of a degree): what the percepts tell, and short in files; no -0. */
    private static double round(double value) {
        return Math.rint(value * 100) / 100 + 0.0;
    }
}
