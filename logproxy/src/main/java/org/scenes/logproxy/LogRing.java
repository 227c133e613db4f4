package org.scenes.logproxy;

import java.nio.ByteBuffer;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;

/**
 * The only memory between the forwarding thread (single producer) and the log writer (single
 * consumer): a fixed byte ring holding records {@code [length, type, session, nanos, payload]}.
 *
 * <p>Why this shape: forwarding copies a datagram into the ring (a memory copy, no allocation,
 * no lock, no disk) and moves on; the writer formats and writes at its own pace. Memory is
 * bounded by the ring size whatever the game length. No record is ever dropped: when the ring
 * is full, which needs the disk to stall for minutes at game rates, the producer waits for the
 * writer to free space. A forwarded datagram is therefore always logged, at the price of
 * forwarding pausing while the disk is stalled; the waits are counted in {@link ProxyStats}.
 * A writer that fails keeps consuming (and discarding), so forwarding never waits on a dead
 * disk.
 */
final class LogRing {
    static final int HEADER = 24;
    private static final int PADDING = -1;

    private final byte[] data;
    private final ByteBuffer view;
    private final int capacity;
    /** Bytes ever written; the producer owns it, the consumer reads it. */
    private final AtomicLong tail = new AtomicLong();
    /** Bytes ever consumed; the consumer owns it, the producer reads it. */
    private final AtomicLong head = new AtomicLong();
    private volatile Thread consumer;
    private volatile long highWater;
    private volatile long waits;

    LogRing(int capacity) {
        this.capacity = capacity & ~7;
        this.data = new byte[this.capacity];
        this.view = ByteBuffer.wrap(data);
    }

    void consumer(Thread thread) {
        this.consumer = thread;
    }

    /** Receives records in the order they were published. */
    interface RecordHandler {
        void record(int type, int session, long nanos, byte[] data, int offset, int length);
    }

    /** Publishes bytes {@code [from, to)} of {@code source} (absolute indices, position untouched). */
    void publish(int type, int session, long nanos, ByteBuffer source, int from, int to) {
        int length = to - from;
        int offset = reserve(HEADER + length);
        writeHeader(offset, HEADER + length, type, session, nanos);
        source.get(from, data, offset + HEADER, length);
        commit(HEADER + length);
    }

    void publish(int type, int session, long nanos, byte[] payload) {
        int offset = reserve(HEADER + payload.length);
        writeHeader(offset, HEADER + payload.length, type, session, nanos);
        System.arraycopy(payload, 0, data, offset + HEADER, payload.length);
        commit(HEADER + payload.length);
    }

    private long pendingCommit;

    /** Finds room for a record, wrapping with a padding record; waits while the ring is full. */
    private int reserve(int size) {
        int aligned = align(size);
        if (aligned > capacity / 2) {
            throw new IllegalArgumentException("record of " + size + " bytes exceeds half the log buffer");
        }
        long position = tail.get();
        int offset = (int) (position % capacity);
        int skip = offset + aligned > capacity ? capacity - offset : 0;
        awaitRoom(position, skip + aligned);
        if (skip > 0) {
            view.putInt(offset, PADDING);
            position += skip;
            tail.set(position);
            offset = 0;
        }
        pendingCommit = position;
        return offset;
    }

    private void awaitRoom(long position, int needed) {
        long used = position - head.get();
        if (capacity - used < needed) {
            waits++;
            do {
                Thread writer = consumer;
                if (writer != null) {
                    LockSupport.unpark(writer);
                }
                LockSupport.parkNanos(50_000);
                used = position - head.get();
            } while (capacity - used < needed);
        }
        if (used + needed > highWater) {
            highWater = used + needed;
        }
    }

    private void writeHeader(int offset, int length, int type, int session, long nanos) {
        view.putInt(offset, length);
        view.putInt(offset + 4, type);
        view.putInt(offset + 8, session);
        view.putLong(offset + 16, nanos);
    }

    private void commit(int size) {
        tail.set(pendingCommit + align(size));
    }

    private static int align(int size) {
        return (size + 7) & ~7;
    }

    /** Hands every published record to {@code handler}; returns how many there were. */
    int drain(RecordHandler handler) {
        long position = head.get();
        long end = tail.get();
        int count = 0;
        while (position < end) {
            int offset = (int) (position % capacity);
            int length = view.getInt(offset);
            if (length == PADDING) {
                position += capacity - offset;
            } else {
                handler.record(view.getInt(offset + 4), view.getInt(offset + 8), view.getLong(offset + 16),
                        data, offset + HEADER, length - HEADER);
                position += align(length);
                count++;
            }
            head.set(position);
        }
        return count;
    }

    boolean isEmpty() {
        return head.get() == tail.get();
    }

    long highWater() {
        return highWater;
    }

    long waits() {
        return waits;
    }
}
