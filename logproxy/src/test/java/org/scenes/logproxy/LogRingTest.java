package org.scenes.logproxy;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Test;

class LogRingTest {
    private record Seen(int type, int session, long nanos, byte[] payload) {
    }

    @Test
    void recordsComeOutInOrderAcrossWrapsWithASlowConsumer() throws Exception {
        LogRing ring = new LogRing(ProxyConfig.MIN_LOG_BUFFER_BYTES);
        int count = 20_000;
        Random random = new Random(42);
        List<byte[]> payloads = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            byte[] payload = new byte[i % 500 == 0 ? 65_000 : random.nextInt(300)];
            random.nextBytes(payload);
            payloads.add(payload);
        }
        List<Seen> seen = new ArrayList<>();
        Thread consumer = new Thread(() -> {
            while (seen.size() < count) {
                int drained = ring.drain((type, session, nanos, data, offset, length) ->
                        seen.add(new Seen(type, session, nanos, Arrays.copyOfRange(data, offset, offset + length))));
                if (drained == 0) {
                    LockSupport.parkNanos(200_000); // slower than the producer: the ring fills up
                }
            }
        });
        ring.consumer(consumer);
        consumer.start();
        for (int i = 0; i < count; i++) {
            byte[] payload = payloads.get(i);
            if (i % 2 == 0) {
                ring.publish(RecordType.TO_SERVER, i, i * 10L, payload);
            } else {
                // From a buffer, with bytes before and after that must not be copied.
                ByteBuffer buffer = ByteBuffer.allocateDirect(payload.length + 8);
                buffer.position(3);
                buffer.put(payload);
                ring.publish(RecordType.TO_CLIENT, i, i * 10L, buffer, 3, 3 + payload.length);
            }
        }
        consumer.join(60_000);
        assertEquals(count, seen.size());
        for (int i = 0; i < count; i++) {
            Seen record = seen.get(i);
            assertEquals(i, record.session());
            assertEquals(i * 10L, record.nanos());
            assertEquals(i % 2 == 0 ? RecordType.TO_SERVER : RecordType.TO_CLIENT, record.type());
            assertArrayEquals(payloads.get(i), record.payload(), "record " + i);
        }
        assertTrue(ring.isEmpty());
        assertTrue(ring.highWater() <= ProxyConfig.MIN_LOG_BUFFER_BYTES);
    }

    @Test
    void aFullRingMakesTheProducerWaitAndLosesNothing() throws Exception {
        LogRing ring = new LogRing(ProxyConfig.MIN_LOG_BUFFER_BYTES);
        int count = 20;
        byte[] payload = new byte[60_000];
        Thread producer = new Thread(() -> {
            for (int i = 0; i < count; i++) {
                payload[0] = (byte) i;
                ring.publish(RecordType.TO_CLIENT, 7, i, payload);
            }
        });
        producer.start();
        long deadline = System.currentTimeMillis() + 30_000;
        while (ring.waits() == 0) {
            assertTrue(System.currentTimeMillis() < deadline, "the producer never found the ring full");
            Thread.sleep(1);
        }
        assertTrue(producer.isAlive(), "no consumer yet: the producer must be waiting");
        List<Byte> firstBytes = new ArrayList<>();
        while (producer.isAlive() || !ring.isEmpty()) {
            ring.drain((type, session, nanos, data, offset, length) -> {
                assertEquals(60_000, length);
                firstBytes.add(data[offset]);
            });
            assertTrue(System.currentTimeMillis() < deadline, "the producer never finished");
        }
        assertEquals(count, firstBytes.size());
        for (int i = 0; i < count; i++) {
            assertEquals((byte) i, firstBytes.get(i));
        }
    }
}
