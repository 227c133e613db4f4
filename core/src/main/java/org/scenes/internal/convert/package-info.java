/**
 * Conversion of player logs (the logging proxy's, the classic {@code .lsf}, captures) into scenes.
 *
 * <p><b>Internal:</b> part of the scenes implementation, public only for the project's own modules.
 * Plugins must not depend on it (they use {@link org.scenes.api}); it may change without notice.
 */
package org.scenes.internal.convert;
