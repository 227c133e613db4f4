/**
 * What the server knows of a game, cycle by cycle: {@link org.scenes.internal.gamelog.GameFrame} is one
 * cycle's state of ball and players, the content of one {@code show} of a server game log
 * ({@code .rcg}). The embedded simulator emits frames as it plays; game-log writers and readers,
 * closed-loop evaluation and the replay page all speak in frames.
 *
 * <p><b>Internal:</b> part of the scenes implementation, public only for the project's own modules.
 * Plugins must not depend on it (they use {@link org.scenes.api}); it may change without notice.
 */
package org.scenes.internal.gamelog;
