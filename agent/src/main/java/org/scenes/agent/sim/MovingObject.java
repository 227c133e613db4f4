package org.scenes.agent.sim;

/** Position, velocity and this cycle's acceleration of the ball or a player. */
class MovingObject {
    double x;
    double y;
    double vx;
    double vy;
    double ax;
    double ay;

    final void place(double newX, double newY) {
        x = newX;
        y = newY;
        vx = 0;
        vy = 0;
        ax = 0;
        ay = 0;
    }

    final double speed() {
        return Math.hypot(vx, vy);
    }

    final double distanceTo(MovingObject other) {
        return Math.hypot(other.x - x, other.y - y);
    }

    /** Adds acceleration, capped so that it has at most {@code max} magnitude. */
    final void accelerate(double dx, double dy, double max) {
        double length = Math.hypot(dx, dy);
        if (length > max) {
            dx *= max / length;
            dy *= max / length;
        }
        ax += dx;
        ay += dy;
    }
}
