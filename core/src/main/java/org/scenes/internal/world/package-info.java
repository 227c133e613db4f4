/**
 * The world model a scene carries ({@link org.scenes.api.World}): self-localisation from the seen
 * landmarks, the ball and players in field coordinates, stamina and the referee's calls, built from
 * a player's percepts by one code path for player logs, game logs and live play (docs/scene-format.md,
 * docs/conversion.md).
 *
 * <p><b>Internal:</b> part of the scenes implementation, public only for the project's own modules.
 * Plugins must not depend on it (they use {@link org.scenes.api}); it may change without notice.
 */
package org.scenes.internal.world;
