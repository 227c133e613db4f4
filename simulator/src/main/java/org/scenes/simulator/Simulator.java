package org.scenes.simulator;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.function.Consumer;
import java.util.function.IntConsumer;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.GameFrame;

/**
 * An embedded soccer server: plays one game between in-process brains that exchange version 9
 * protocol text with the {@link Engine}, synchronously, step by step (100 ms of game time each):
 * every step each player gets {@code sense_body}, the referee's announcements and, on two steps
 * of three (a {@code see} every 150 ms), {@code see}; then the commands the brains sent are
 * executed (one world-changing command per player and step), the world moves and the referee
 * judges. Everything random comes from the setup's seed, so a game repeats byte for byte.
 */
public final class Simulator {
    private final GameSetup setup;
    private final Engine engine;
    private final List<Client> clients = new ArrayList<>();
    private Path recordDirectory;
    private List<Path> recorded = List.of();

    public Simulator(GameSetup setup) {
        this.setup = setup;
        this.engine = new Engine(setup.cycles(), setup.seed());
    }

    /**
     * Also writes the server's logs of the game into {@code directory}: the game log
     * ({@code .rcg}) and the command log ({@code .rcl}), see {@link GameRecorder}.
     */
    public Simulator recordTo(Path directory) {
        this.recordDirectory = directory;
        return this;
    }

    /** The server logs written by the last {@link #run} with {@link #recordTo}: game log, command log. */
    public List<Path> recorded() {
        return recorded;
    }

    /**
     * The seed of the brain in a seat, derived from the game seed: a client connecting over UDP
     * gets the same random choices as in process when it seeds its brain the same way.
     */
    public static long brainSeed(long gameSeed, Side side, int unum) {
        return gameSeed * 1_000_003L + (side == Side.LEFT ? 0 : 100) + unum;
    }

    /** Plays the whole game; {@code progress} is told the game clock after every step. */
    public GameResult run(IntConsumer progress) throws IOException {
        return run(progress, frame -> { });
    }

    /**
     * Plays the whole game; {@code frames} gets the state after the players connected and after
     * every step (what a game log records), {@code progress} the game clock after every step.
     */
    public GameResult run(IntConsumer progress, Consumer<GameFrame> frames) throws IOException {
        GameRecorder recorder = recordDirectory == null ? null : GameRecorder.open(recordDirectory, engine);
        try {
            engine.record(recorder);
            connect(setup.left(), Side.LEFT);
            connect(setup.right(), Side.RIGHT);
            frames.accept(engine.frame());
            while (engine.sense()) {
                frames.accept(engine.advance());
                progress.accept(engine.time());
            }
            List<Path> logs = new ArrayList<>();
            for (Client client : clients) {
                if (client.log() != null) {
                    logs.add(client.log().commit());
                }
            }
            if (recorder != null) {
                recorded = recorder.commit();
            }
            return new GameResult(engine.scoreLeft(), engine.scoreRight(), engine.kicksLeft(), engine.kicksRight(),
                    engine.time(), engine.steps(), logs);
        } catch (UncheckedIOException e) {
            throw e.getCause();
        } finally {
            for (Client client : clients) {
                if (client.log() != null) {
                    client.log().close();
                }
            }
            if (recorder != null) {
                recorder.close();
            }
        }
    }

    private void connect(GameSetup.Team team, Side side) throws IOException {
        for (int unum = 1; unum <= team.players(); unum++) {
            // Each brain gets its own random source derived from the game seed and its seat.
            Random random = new Random(brainSeed(setup.seed(), side, unum));
            Brain brain = team.brains().create(team.name(), random);
            PlayerLog log = setup.logDirectory() == null ? null
                    : new PlayerLog(setup.logDirectory().resolve(team.name() + "_" + unum + ".lsf.gz"));
            Client client = new Client(brain, log, engine);
            clients.add(client);
            boolean goalie = team.brains().goalie(unum);
            String init = "(init " + team.name() + " (version 9)" + (goalie ? " (goalie)" : "") + ")";
            client.sentByClient(init);
            Seat seat;
            try {
                seat = engine.join(team.name(), 9, goalie, init, client::deliver);
            } catch (Engine.Refused e) {
                throw new IllegalStateException("the engine refused " + team.name() + " " + unum + ": " + e.answer());
            }
            if (seat.side() != side || seat.unum() != unum) {
                throw new IllegalStateException("the engine seated " + team.name() + " " + unum + " elsewhere");
            }
            client.seat(seat);
            engine.welcome(seat);
            // The real server executes commands as they arrive before kick-off, such as the first move.
            engine.executePending(seat);
        }
    }
}
