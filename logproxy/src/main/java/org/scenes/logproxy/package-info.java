/**
 * The UDP logging proxy that records agents playing ({@code scenes proxy}).
 *
 * <p>Public surface: {@link org.scenes.logproxy.LogProxy} (start, ports, stats, close),
 * {@link org.scenes.logproxy.ProxyConfig}, {@link org.scenes.logproxy.Route},
 * {@link org.scenes.logproxy.ClientKind}, {@link org.scenes.logproxy.ProxyStats}, and
 * {@link org.scenes.logproxy.ProxyEnvironment} for tests that drive its clock or make its disk
 * stall; it writes the formats {@code org.scenes.internal.convert.LogFormat} names. Inside, a
 * forwarding thread (one selector, one socket
 * towards the server per client) hands copies of datagrams to a log writer thread through a
 * fixed byte ring; the file format is {@code docs/proxy-log-format.md}, read back with
 * {@code org.scenes.internal.proxylog}.
 */
package org.scenes.logproxy;
