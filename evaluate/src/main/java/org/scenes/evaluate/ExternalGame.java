package org.scenes.evaluate;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.time.Duration;
import java.util.function.IntConsumer;
import org.scenes.agent.net.ClientOptions;
import org.scenes.api.Side;
import org.scenes.simulator.GameSetup;

/**
 * One game of two external teams on a live server, none of ours on the pitch. The first team to
 * join a server plays on the left, so the left team's command is started first, through a
 * {@link TeamRelay} that tells when all its players were accepted (and, from then on, the clock
 * and the referee they hear); only then is the right team's command started, straight to the
 * server. Both commands' process groups are ended after the game, and a command that ends before
 * the game began, whose players do not join within {@code serverWait}, or whose group ends before
 * time over fails the game with one line naming it.
 */
final class ExternalGame {
    private static final long POLL_MILLIS = 200;

    private final ClientOptions client;
    private final Duration serverWait;

    ExternalGame(ClientOptions client, Duration serverWait) {
        this.client = client;
        this.serverWait = serverWait;
    }

    /**
     * Plays the game to time over, telling {@code board} what the left team hears; returns when
     * the server took the game (its left team complete), for finding the game's log.
     */
    FileTime play(GameSetup setup, LiveArena.Scoreboard board, IntConsumer progress)
            throws IOException, InterruptedException {
        GameSetup.Team left = setup.left();
        GameSetup.Team right = setup.right();
        ExternalTeam leftCommand = (ExternalTeam) left.brains();
        ExternalTeam rightCommand = (ExternalTeam) right.brains();
        String host = client.server().host();
        int port = client.server().port();
        Path leftOutput = Files.createTempFile("scenes-team-" + left.name() + "-", ".log");
        Path rightOutput = Files.createTempFile("scenes-team-" + right.name() + "-", ".log");
        try (TeamRelay relay = new TeamRelay(new InetSocketAddress(host, port), board);
             ExternalTeam.Running first = leftCommand.start(relay.host(), relay.port(), left.name(), left.players(),
                     leftOutput)) {
            long deadline = System.nanoTime() + serverWait.toNanos();
            while (relay.accepted() < left.players()) {
                if (relay.side() == Side.RIGHT) {
                    throw new IOException(left.name() + ": the command '" + first.command() + "' was given the right"
                            + " side by " + client.server() + ": is another team connected?");
                }
                if (!first.alive()) {
                    throw endedBeforeTheGame(left, first);
                }
                if (System.nanoTime() > deadline) {
                    throw notJoined(left, first, relay.accepted());
                }
                Thread.sleep(POLL_MILLIS);
            }
            FileTime begun = FileTime.fromMillis(System.currentTimeMillis());
            try (ExternalTeam.Running second = rightCommand.start(host, port, right.name(), right.players(),
                    rightOutput)) {
                deadline = System.nanoTime() + serverWait.toNanos();
                // the server kicks off only with both teams there: the left team's clock runs once the right joined
                while (board.time.get() < 1 && !board.timeOver) {
                    if (!first.alive()) {
                        throw endedBeforeTheGame(left, first);
                    }
                    if (!second.alive()) {
                        throw endedBeforeTheGame(right, second);
                    }
                    if (System.nanoTime() > deadline) {
                        throw notJoined(right, second, 0);
                    }
                    Thread.sleep(POLL_MILLIS);
                }
                long silence = client.silenceTimeout().toNanos();
                while (!board.timeOver) {
                    progress.accept(board.time.get());
                    Thread.sleep(POLL_MILLIS);
                    if (board.timeOver) {
                        break;
                    }
                    for (ExternalTeam.Running running : new ExternalTeam.Running[] {first, second}) {
                        if (!running.alive()) {
                            GameSetup.Team team = running == first ? left : right;
                            throw new IOException(team.name() + ": the command '" + running.command() + "' ended (exit "
                                    + running.exitCode() + ") at cycle " + board.time.get() + ", before time over"
                                    + LiveArena.quoted(running.lastWords()));
                        }
                    }
                    if (System.nanoTime() - relay.lastHeard() > silence) {
                        throw new IOException(left.name() + ": no message from the server at " + client.server()
                                + " for " + client.silenceTimeout().toSeconds() + " s at cycle " + board.time.get()
                                + ", before time over");
                    }
                }
            }
            return begun;
        } finally {
            Files.deleteIfExists(leftOutput);
            Files.deleteIfExists(rightOutput);
        }
    }

    private static IOException endedBeforeTheGame(GameSetup.Team team, ExternalTeam.Running running) {
        return new IOException(team.name() + ": the command '" + running.command() + "' ended (exit "
                + running.exitCode() + ") before the game began" + LiveArena.quoted(running.lastWords()));
    }

    private IOException notJoined(GameSetup.Team team, ExternalTeam.Running running, int joined) {
        return new IOException(team.name() + ": " + (joined == 0 ? "no player" : "only " + joined + " of "
                + team.players() + " players") + " of the command '" + running.command() + "' joined the game on "
                + client.server() + " within " + serverWait.toSeconds() + " s" + LiveArena.quoted(running.lastWords()));
    }
}
