package org.scenes.evaluate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.scenes.api.Side;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.teacher.Teachers;

/**
 * The relay that watches an external team joining a game of two external teams, against a
 * server played by hand on loopback; and the side each plan's teams take.
 */
class TeamRelayTest {
    private static final InetAddress LOOPBACK = InetAddress.getLoopbackAddress();

    @Test
    void theRelayFollowsThePortSwitchSaysTheInitAgainAndTellsTheScoreboardWhatThePlayerHears() throws Exception {
        LiveArena.Scoreboard board = new LiveArena.Scoreboard();
        try (DatagramChannel initPort = open(); DatagramChannel ownPort = open(); DatagramChannel player = open();
             TeamRelay relay = new TeamRelay((InetSocketAddress) initPort.getLocalAddress(), board)) {
            InetSocketAddress relayAddress = new InetSocketAddress(relay.host(), relay.port());
            send(player, "(init Teal (version 9))", relayAddress);
            // the server is not listening yet (rcssserver restarting between games): the first init is lost
            assertEquals("(init Teal (version 9))", receive(initPort).text());
            long first = System.nanoTime();
            Received again = receive(initPort);
            assertEquals("(init Teal (version 9))", again.text());
            assertTrue(System.nanoTime() - first > 800_000_000L, "said again after about a second");
            assertEquals(0, relay.accepted());
            assertNull(relay.side());
            // answered from a port of the server's own, as rcssserver answers
            send(ownPort, "(init l 3 before_kick_off)", again.from());
            assertEquals("(init l 3 before_kick_off)", receive(player).text());
            assertEquals(1, relay.accepted());
            assertEquals(Side.LEFT, relay.side());
            send(player, "(dash 50)", relayAddress);
            Received dash = receive(ownPort);
            assertEquals("(dash 50)", dash.text());
            assertEquals(again.from(), dash.from(), "the player's own upstream socket");
            send(ownPort, "(sense_body 42 (view_mode high normal) (kick 1) (dash 2))", dash.from());
            send(ownPort, "(hear 43 referee time_over)", dash.from());
            assertTrue(receive(player).text().startsWith("(sense_body 42"));
            assertEquals("(hear 43 referee time_over)", receive(player).text());
            assertEquals(43, board.time.get(), "the clock, to time over");
            assertTrue(board.timeOver);
            assertEquals(1, board.kicks(Side.LEFT), "the kick counter heard");
            // no init goes out again once answered
            initPort.configureBlocking(false);
            Thread.sleep(1200);
            assertNull(initPort.receive(ByteBuffer.allocate(100)));
            assertTrue(System.nanoTime() - relay.lastHeard() < 2_000_000_000L);
        }
    }

    @Test
    void teacherAndImitatorKeepOneSideForEveryMixOfExternalTeams() {
        ExternalTeam command = new ExternalTeam("true");
        GameSetup.Team ours = new GameSetup.Team("Teal", 2, Teachers.byName("krislet"));
        GameSetup.Team external = new GameSetup.Team("Teal", 2, command);
        GameSetup.Team opponent = new GameSetup.Team("Amber", 2, Teachers.byName("krislet"));
        GameSetup.Team externalOpponent = new GameSetup.Team("Amber", 2, command);
        assertEquals(Side.LEFT, Evaluation.Plan.sideOf(ours.brains(), opponent.brains()));
        assertEquals(Side.RIGHT, Evaluation.Plan.sideOf(external.brains(), opponent.brains()));
        assertEquals(Side.LEFT, Evaluation.Plan.sideOf(ours.brains(), externalOpponent.brains()));
        assertEquals(Side.LEFT, Evaluation.Plan.sideOf(external.brains(), externalOpponent.brains()));
        Evaluation.Plan both = new Evaluation.Plan(external, Teachers.byName("krislet"), externalOpponent, 100,
                List.of(1L));
        assertEquals(Side.LEFT, both.side());
        assertTrue(both.external());
        assertNull(both.shadow(), "no shadow in process for an external teacher");
        IllegalArgumentException wrong = assertThrows(IllegalArgumentException.class, () -> new Evaluation.Plan(
                external, Teachers.byName("krislet"), externalOpponent, 100, List.of(1L), Side.RIGHT));
        assertTrue(wrong.getMessage().startsWith("teacher and imitator play on the left side"), wrong.getMessage());
        assertFalse(new Evaluation.Plan(ours, Teachers.byName("krislet"), opponent, 100, List.of(1L)).external());
    }

    private static DatagramChannel open() throws Exception {
        DatagramChannel channel = DatagramChannel.open();
        channel.bind(new InetSocketAddress(LOOPBACK, 0));
        return channel;
    }

    private static void send(DatagramChannel channel, String text, SocketAddress to) throws Exception {
        channel.send(ByteBuffer.wrap((text + '\0').getBytes(StandardCharsets.UTF_8)), to);
    }

    private record Received(String text, SocketAddress from) {
    }

    /** The next datagram, waiting at most 5 s. */
    private static Received receive(DatagramChannel channel) throws Exception {
        channel.configureBlocking(true);
        channel.socket().setSoTimeout(5000);
        java.net.DatagramPacket packet = new java.net.DatagramPacket(new byte[4096], 4096);
        channel.socket().receive(packet);
        int end = packet.getLength();
        while (end > 0 && packet.getData()[end - 1] == 0) {
            end--;
        }
        return new Received(new String(packet.getData(), 0, end, StandardCharsets.UTF_8), packet.getSocketAddress());
    }
}
