package org.scenes.simulator;

/** The ball. */
final class Ball extends MovingObject {
}
