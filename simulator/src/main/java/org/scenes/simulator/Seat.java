package org.scenes.simulator;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import org.scenes.api.Side;

/**
 * One connected player as the server sees it: its place in the game, the protocol version it
 * speaks, its view mode, and the commands it sent that wait to be executed. Messages for the
 * client go to {@code out}, in order.
 */
public final class Seat {
    final Player player;
    final int version;
    Consumer<String> out;
    /** Commands received since the engine last executed this seat's commands. */
    final List<String> pending = new ArrayList<>();
    /** Cycles a goalie must wait after a catch attempt ({@code catch_ban_cycle}). */
    int catchBan;
    boolean connected = true;
    /** rcssserver's synchronous see counter, and the first step it rises in (the one after the connection). */
    int seeCount;
    int seeCountFrom;

    Seat(Player player, int version, Consumer<String> out) {
        this.player = player;
        this.version = version;
        this.out = out;
    }

    public Side side() {
        return player.side;
    }

    public int unum() {
        return player.unum;
    }

    public String team() {
        return player.team;
    }

    public int version() {
        return version;
    }

    public boolean goalie() {
        return player.goalie;
    }

    /** Whether the player is still in the game (not gone with {@code bye} or dropped). */
    public boolean connected() {
        return connected;
    }

    void send(String message) {
        out.accept(message);
    }

    @Override
    public String toString() {
        return player.team + "_" + player.unum;
    }
}
