/**
 * Actions as targets: what a recorded command achieved in the field (the direction the body came
 * to face, the way the player ran, the ball velocity a kick produced, where the head looked),
 * reached again from another player's own state.
 */
package org.scenes.internal.target;
