package org.scenes.logproxy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class SessionIdentityTest {
    private static SessionIdentity exchange(String client, String... server) {
        SessionIdentity identity = new SessionIdentity();
        identity.fromClient(client);
        for (String reply : server) {
            identity.fromServer(reply);
        }
        return identity;
    }

    @Test
    void player() {
        SessionIdentity identity = exchange("(init Carleton (version 9))", "(init r 3 before_kick_off)");
        assertEquals("Carleton_3", identity.fileStem());
        assertEquals("team Carleton unum 3 side r", identity.description());
    }

    @Test
    void goalieAndPadding() {
        assertEquals("Kris-A_1", exchange("(init Kris-A (version 19) (goalie))", "(init l 1 before_kick_off)").fileStem());
    }

    @Test
    void coachTrainerAndReconnect() {
        assertEquals("Carleton_coach", exchange("(init Carleton (version 9))", "(init l ok)").fileStem());
        assertEquals("trainer", exchange("(init (version 9))", "(init ok)").fileStem());
        assertEquals("University_4", exchange("(reconnect University 4)", "(reconnect r play_on)").fileStem());
    }

    @Test
    void refusedClientStaysUnknown() {
        SessionIdentity identity = exchange("(init Carleton (version 20))",
                "(error no_more_player_or_goalie_or_illegal_client_version)");
        assertFalse(identity.complete());
        assertNull(identity.fileStem());
    }

    @Test
    void unsafeTeamNamesMakeSafeFileNames() {
        SessionIdentity identity = exchange("(init ../etc (version 9))", "(init l 2 before_kick_off)");
        assertTrue(identity.complete());
        assertEquals("___etc_2", identity.fileStem());
    }
}
