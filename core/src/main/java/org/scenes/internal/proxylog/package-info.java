/**
 * The native proxy log format written by {@code scenes proxy} ({@code docs/proxy-log-format.md}):
 * one datagram per line, {@code <seconds> <c2s|s2c> <escaped message>}. Shared by the proxy,
 * which writes it, and the converter, which reads it: {@link org.scenes.internal.proxylog.ProxyLogLine}
 * parses and formats a line, {@link org.scenes.internal.proxylog.MessageEscapes} escapes and unescapes a
 * message exactly.
 *
 * <p><b>Internal:</b> part of the scenes implementation, public only for the project's own modules.
 * Plugins must not depend on it (they use {@link org.scenes.api}); it may change without notice.
 */
package org.scenes.internal.proxylog;
