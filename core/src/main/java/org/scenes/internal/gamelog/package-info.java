/**
 * What the server knows of a game, cycle by cycle: {@link org.scenes.internal.gamelog.GameFrame} is one
 * cycle's state of ball and players, the content of one {@code show} of a server game log
 * ({@code .rcg}). The embedded simulator emits frames as it plays; game-log writers and readers,
 * closed-loop evaluation and the replay page all speak in frames.
 */
package org.scenes.internal.gamelog;
