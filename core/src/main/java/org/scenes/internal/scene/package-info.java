/**
 * Scene files: their header, reader and writer, and the vision table.
 *
 * <p><b>Internal:</b> part of the scenes implementation, public only for the project's own modules.
 * Plugins must not depend on it (they use {@link org.scenes.api}); it may change without notice.
 */
package org.scenes.internal.scene;
