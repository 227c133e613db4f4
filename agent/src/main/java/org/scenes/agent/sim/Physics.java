package org.scenes.agent.sim;

import java.util.List;
import org.scenes.scene.Side;

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
        if (!world.mode.clockRuns) {
            return; // dashes before kick-off and during pauses cost stamina but do not move
        }
        double acceleration = power * p.dashPowerRate() * player.effort;
        double angle = Math.toRadians(player.body);
        player.accelerate(acceleration * Math.cos(angle), acceleration * Math.sin(angle), p.playerAccelMax());
    }

    void turn(Player player, double moment) {
        moment = clamp(moment, p.minMoment(), p.maxMoment());
        player.body = Numbers.normalize(player.body + moment / (1 + p.inertiaMoment() * player.speed()));
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
     * touched. Like the server, the counter counts every executed kick command, touch or not.
     */
    boolean kick(Player player, double power, double direction) {
        player.kicks++;
        Ball ball = world.ball;
        double distance = player.distanceTo(ball);
        if (distance > p.kickableDistance()) {
            return false;
        }
        power = clamp(power, p.minPower(), p.maxPower());
        direction = clamp(direction, p.minMoment(), p.maxMoment());
        double ballAngle = Math.toDegrees(Math.atan2(ball.y - player.y, ball.x - player.x));
        double dirDiff = Math.abs(Numbers.normalize(ballAngle - player.body));
        double gap = Math.max(0, distance - p.playerSize() - p.ballSize());
        double rate = 1 - 0.25 * dirDiff / 180 - 0.25 * gap / p.kickableMargin();
        double effective = power * p.kickPowerRate() * rate;
        double angle = Math.toRadians(player.body + direction);
        // Kick noise grows with power and with a badly placed ball.
        double noise = p.kickRand() * Math.abs(power) / p.maxPower()
                * (0.5 + 0.25 * (dirDiff / 180 + gap / p.kickableMargin()));
        ball.accelerate(effective * Math.cos(angle) + world.noise(noise),
                effective * Math.sin(angle) + world.noise(noise), p.ballAccelMax());
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
        List<Player> players = world.players;
        for (int i = 0; i < players.size(); i++) {
            for (int j = i + 1; j < players.size(); j++) {
                separate(players.get(i), players.get(j));
            }
        }
        for (Player player : players) {
            collide(player, ball);
        }
    }

    /** Two overlapping players are pushed apart, each by half the overlap, and both bounce. */
    private void separate(Player a, Player b) {
        double minimum = 2 * p.playerSize();
        double dx = b.x - a.x;
        double dy = b.y - a.y;
        double distance = Math.hypot(dx, dy);
        if (distance >= minimum) {
            return;
        }
        if (distance < 1e-9) {
            // Exactly on top of each other: part them along the first one's body direction.
            dx = Math.cos(Math.toRadians(a.body));
            dy = Math.sin(Math.toRadians(a.body));
            distance = 1;
            a.x -= dx * minimum / 2;
            a.y -= dy * minimum / 2;
            b.x = a.x + dx * minimum;
            b.y = a.y + dy * minimum;
        } else {
            double push = (minimum - distance) / 2 / distance;
            a.x -= dx * push;
            a.y -= dy * push;
            b.x += dx * push;
            b.y += dy * push;
        }
        a.vx *= -0.1;
        a.vy *= -0.1;
        b.vx *= -0.1;
        b.vy *= -0.1;
    }

    /**
     * A ball overlapping a player is put back at the player's edge and both bounce, as on the
     * server (velocities times -0.1).
     */
    private void collide(Player player, Ball ball) {
        double minimum = p.playerSize() + p.ballSize();
        double dx = ball.x - player.x;
        double dy = ball.y - player.y;
        double distance = Math.hypot(dx, dy);
        if (distance >= minimum) {
            return;
        }
        if (distance < 1e-9) {
            dx = Math.cos(Math.toRadians(player.body));
            dy = Math.sin(Math.toRadians(player.body));
            distance = 1;
        }
        ball.x = player.x + dx / distance * minimum;
        ball.y = player.y + dy / distance * minimum;
        ball.vx *= -0.1;
        ball.vy *= -0.1;
        player.vx *= -0.1;
        player.vy *= -0.1;
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
        // Uniform noise proportional to the speed, on each axis.
        double range = rand * speed;
        ux += world.noise(range);
        uy += world.noise(range);
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
