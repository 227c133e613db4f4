package org.scenes.simulator;

/** Position, velocity and this cycle's acceleration of the ball or a player. */
class MovingObject {
    double x;
    double y;
    double vx;
    double vy;
    double ax;
    double ay;
    /** This cycle's collisions: the sum of the positions they ask for, how many, whether any. */
    double collisionX;
    double collisionY;
    int collisionCount;
    boolean collided;

    final void place(double newX, double newY) {
        x = newX;
        y = newY;
        vx = 0;
        vy = 0;
        ax = 0;
        ay = 0;
    }

    /** A collision asks this object to stand at (x, y); several are averaged. */
    final void collide(double atX, double atY) {
        collisionX += atX;
        collisionY += atY;
        collisionCount++;
        collided = true;
    }

    /** Moves to the mean position the collisions asked for, and forgets them. */
    final void moveToCollisionPosition() {
        if (collisionCount > 0) {
            x = collisionX / collisionCount;
            y = collisionY / collisionCount;
        }
        collisionX = 0;
        collisionY = 0;
        collisionCount = 0;
    }

    /** After the cycle's collisions: an object that collided bounces back at a tenth of its speed. */
    final void bounceIfCollided() {
        if (collided) {
            vx *= -0.1;
            vy *= -0.1;
            collided = false;
        }
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
