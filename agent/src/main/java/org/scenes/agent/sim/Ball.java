package org.scenes.agent.sim;

/** The ball. */
final class Ball extends MovingObject {
}
