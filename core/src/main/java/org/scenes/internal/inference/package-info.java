/**
 * The commands the players executed, inferred from a game log alone ({@code .rcg}, no {@code .rcl}):
 * which commands from the counters of each show, their arguments by inverting rcssserver's turn,
 * dash, kick and neck models ({@link org.scenes.internal.inference.CommandInference}), as a command
 * source for game-log conversion ({@link org.scenes.internal.inference.InferredCommandLog}), and its
 * check against a real command log ({@link org.scenes.internal.inference.CommandCheck}).
 *
 * <p><b>Internal:</b> part of the scenes implementation, public only for the project's own modules.
 */
package org.scenes.internal.inference;
