package org.scenes.logproxy;

/**
 * Counters since the proxy started.
 *
 * @param toServer datagrams forwarded from clients to the server
 * @param toClients datagrams forwarded from the server to clients
 * @param notForwarded datagrams received but not sent on (socket errors, outbox overflow,
 *     session closed with sends pending); they are still in the logs
 * @param logged messages written to log files
 * @param sessionsOpened clients seen
 * @param sessionsClosed clients whose log is complete
 * @param logBufferHighWater most bytes ever waiting between forwarding and the writer
 * @param logBufferWaits times forwarding had to wait for the writer (buffer full)
 * @param logErrors I/O errors of the log writer
 */
public record ProxyStats(long toServer, long toClients, long notForwarded, long logged, long sessionsOpened,
        long sessionsClosed, long logBufferHighWater, long logBufferWaits, long logErrors) {
}
