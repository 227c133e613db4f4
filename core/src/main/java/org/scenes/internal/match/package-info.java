/**
 * Matching: knowledge bases, the recognizer that finds the nearest stored scenes, indexes and packed scans.
 *
 * <p><b>Internal:</b> part of the scenes implementation, public only for the project's own modules.
 * Plugins must not depend on it (they use {@link org.scenes.api}); it may change without notice.
 */
package org.scenes.internal.match;
