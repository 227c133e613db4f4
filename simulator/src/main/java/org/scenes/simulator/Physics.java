package org.scenes.simulator;

import java.util.List;
import org.scenes.api.Side;

/**
 * The server's body model: dash, turn, turn_neck, kick and move change a player or the ball;
 * {@link #step} moves everything one cycle (accelerate, add noise, move, decay) and updates
 * stamina. Formulas follow the published server model; docs/simulator.md lists simplifications.
 */
final class Physics {
    private final World world;
    private final ServerParams p;

    Physics(World world) {
        this.world = world;
        this.p = world.params;
    }

    void dash(Player player, double power) {
        power = clamp(power, p.minPower(), p.maxPower());
        // Backward dashes cost twice; a tired player dashes only with the stamina it has.
        double cost = power >= 0 ? power : -2 * power;
        if (cost > player.stamina) {
            cost = Math.max(player.stamina, 0);
            power = power >= 0 ? cost : -cost / 2;
        }
        player.stamina -= cost;
        player.dashes++;
        if (!world.mode.objectsMove) {
            return; // dashes before kick-off cost stamina but do not move
        }
        double acceleration = power * p.dashPowerRate() * player.effort;
        double angle = Math.toRadians(player.body);
        player.accelerate(acceleration * Math.cos(angle), acceleration * Math.sin(angle), p.playerAccelMax());
    }

    void turn(Player player, double moment) {
        moment = clamp(moment, p.minMoment(), p.maxMoment());
        // The server scales each turn by a random factor in [1 - player_rand, 1 + player_rand].
        double noisy = (1 + world.noise(p.playerRand())) * moment;
        player.body = Numbers.normalize(player.body + noisy / (1 + p.inertiaMoment() * player.speed()));
        player.turns++;
    }

    void turnNeck(Player player, double angle) {
        player.neck = clamp(player.neck + clamp(angle, p.minMoment(), p.maxMoment()), p.minNeckAng(),
                p.maxNeckAng());
        player.turnNecks++;
    }

    /** Moves a player to a point given in its own side's frame (the right side is mirrored). */
    void move(Player player, double x, double y) {
        double sign = player.side == Side.LEFT ? 1 : -1;
        player.place(clamp(sign * x, -limitX(), limitX()), clamp(sign * y, -limitY(), limitY()));
        player.moves++;
    }

    /**
     * Kicks the ball when it is within the kickable distance; returns whether the ball was
     * touched. Like the server, the counter counts only kicks that reach the ball (rcssserver
     * returns before counting when the ball is not kickable).
     */
    boolean kick(Player player, double power, double direction) {
        Ball ball = world.ball;
        double distance = player.distanceTo(ball);
        if (distance > p.kickableDistance()) {
            return false;
        }
        player.kicks++;
        power = clamp(power, p.minPower(), p.maxPower());
        direction = clamp(direction, p.minMoment(), p.maxMoment());
        double ballAngle = Math.toDegrees(Math.atan2(ball.y - player.y, ball.x - player.x));
        double dirDiff = Math.abs(Numbers.normalize(ballAngle - player.body));
        double gap = Math.max(0, distance - p.playerSize() - p.ballSize());
        double rate = 1 - 0.25 * dirDiff / 180 - 0.25 * gap / p.kickableMargin();
        double effective = power * p.kickPowerRate() * rate;
        double angle = Math.toRadians(player.body + direction);
        // The server's kick noise: up to kick_rand times the power's share, times the sum of a
        // placement rate (0.5 to 1, worse for a ball off the body's direction or far) and a speed
        // rate (0.5 to 1, worse for a fast ball), as a vector of random length and direction.
        double placement = 0.5 + 0.25 * (dirDiff / 180 + gap / p.kickableMargin());
        double ballSpeed = 0.5 + 0.5 * ball.speed() / (p.ballSpeedMax() * p.ballDecay());
        double[] noise = world.polarNoise(p.kickRand() * Math.abs(power) / p.maxPower() * (placement + ballSpeed));
        ball.accelerate(effective * Math.cos(angle) + noise[0], effective * Math.sin(angle) + noise[1],
                p.ballAccelMax());
        return true;
    }

    /** One simulator step of motion for the ball and every player. */
    void step() {
        Ball ball = world.ball;
        moveObject(ball, p.ballSpeedMax(), p.ballRand(), p.ballDecay());
        for (Player player : world.players) {
            moveObject(player, p.playerSpeedMax(), p.playerRand(), p.playerDecay());
            player.x = clamp(player.x, -limitX(), limitX());
            player.y = clamp(player.y, -limitY(), limitY());
        }
        collisions();
    }

    /**
     * Overlaps resolved as the server resolves them, up to ten rounds while any remain: each round
     * every overlapping pair (ball and player, then player and player) asks both to stand just
     * apart, each object moves to the mean of what was asked of it; at the end everything that
     * collided keeps a tenth of its speed, backwards. A ball touching a player counts as the
     * player's touch for the referee. Outside play on the ball stays and the player steps off it.
     */
    void collisions() {
        Ball ball = world.ball;
        List<Player> players = world.players;
        double ballReach = p.ballSize() + p.playerSize();
        double playerReach = 2 * p.playerSize();
        boolean collided = true;
        for (int round = 0; round < MAX_COLLISION_ROUNDS && collided; round++) {
            collided = false;
            for (Player player : players) {
                if (distance2(ball, player) < ballReach * ballReach) {
                    collided = true;
                    world.lastTouch = player.side;
                    if (world.mode == PlayMode.PLAY_ON) {
                        separate(ball, player, ballReach);
                    } else {
                        stepOff(ball, player, ballReach);
                    }
                }
            }
            for (int i = 0; i < players.size(); i++) {
                for (int j = i + 1; j < players.size(); j++) {
                    if (distance2(players.get(i), players.get(j)) < playerReach * playerReach) {
                        collided = true;
                        separate(players.get(i), players.get(j), playerReach);
                    }
                }
            }
            ball.moveToCollisionPosition();
            for (Player player : players) {
                player.moveToCollisionPosition();
            }
        }
        ball.bounceIfCollided();
        for (Player player : players) {
            player.bounceIfCollided();
        }
    }

    /** The server's tiny margin that leaves two separated objects just apart. */
    private static final double EPS = 1e-10;
    private static final int MAX_COLLISION_ROUNDS = 10;

    private static double distance2(MovingObject a, MovingObject b) {
        double dx = a.x - b.x;
        double dy = a.y - b.y;
        return dx * dx + dy * dy;
    }

    /**
     * Two overlapping objects should stand {@code reach} apart, symmetrically about their midpoint
     * (in a random direction when they coincide).
     */
    private void separate(MovingObject a, MovingObject b, double reach) {
        double midX = (a.x + b.x) / 2;
        double midY = (a.y + b.y) / 2;
        double dx = a.x - midX;
        double dy = a.y - midY;
        double half = reach / 2 + EPS;
        double length = Math.hypot(dx, dy);
        if (length < EPS) {
            double angle = (world.random.nextDouble() * 2 - 1) * Math.PI;
            dx = Math.cos(angle);
            dy = Math.sin(angle);
            length = 1;
        }
        double ux = dx / length;
        double uy = dy / length;
        a.collide(midX + ux * half, midY + uy * half);
        b.collide(midX - ux * half, midY - uy * half);
    }

    /** Outside play on a ball a player runs into stays, and the player is put just off it. */
    private void stepOff(Ball ball, Player player, double reach) {
        double dx = player.x - ball.x;
        double dy = player.y - ball.y;
        double length = Math.hypot(dx, dy);
        if (length == 0) {
            double angle = (world.random.nextDouble() * 2 - 1) * Math.PI;
            dx = Math.cos(angle);
            dy = Math.sin(angle);
            length = 1;
        }
        double distance = reach + EPS;
        ball.collide(ball.x, ball.y);
        player.collide(ball.x + dx / length * distance, ball.y + dy / length * distance);
    }

    /** Stamina, effort and recovery of one cycle, every cycle whether the clock runs or not. */
    void recover(Player player) {
        double max = p.staminaMax();
        if (player.stamina <= p.recoverDecThr() * max && player.recovery > p.recoverMin()) {
            player.recovery = Math.max(p.recoverMin(), player.recovery - p.recoverDec());
        }
        if (player.stamina <= p.effortDecThr() * max && player.effort > p.effortMin()) {
            player.effort = Math.max(p.effortMin(), player.effort - p.effortDec());
        }
        if (player.stamina >= p.effortIncThr() * max && player.effort < 1) {
            player.effort = Math.min(1, player.effort + p.effortInc());
        }
        player.stamina = Math.min(max, player.stamina + player.recovery * p.staminaIncMax());
    }

    private void moveObject(MovingObject object, double speedMax, double rand, double decay) {
        double ux = object.vx + object.ax;
        double uy = object.vy + object.ay;
        double speed = Math.hypot(ux, uy);
        if (speed > speedMax) {
            ux *= speedMax / speed;
            uy *= speedMax / speed;
            speed = speedMax;
        }
        // Noise proportional to the speed: a vector of length up to rand * speed, any direction.
        double[] noise = world.polarNoise(rand * speed);
        ux += noise[0];
        uy += noise[1];
        object.x += ux;
        object.y += uy;
        object.vx = decay * ux;
        object.vy = decay * uy;
        object.ax = 0;
        object.ay = 0;
    }

    private static double limitX() {
        return ServerParams.PITCH_HALF_LENGTH + ServerParams.PITCH_MARGIN;
    }

    private static double limitY() {
        return ServerParams.PITCH_HALF_WIDTH + ServerParams.PITCH_MARGIN;
    }

    static double clamp(double value, double min, double max) {
        return Math.max(min, Math.min(max, value));
    }
}
