package org.scenes.internal.inference;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.CommandLogReader;
import org.scenes.internal.gamelog.CommandSource;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.GameLogException;
import org.scenes.internal.gamelog.GameLogReader;
import org.scenes.internal.gamelog.PlayerState;

/**
 * A command log inferred from a game log alone: for each pair of consecutive shows, what each
 * player executed in the step between them ({@link CommandInference}), as an entry at the first
 * show's cycle and stoppage (the show's place among those of its cycle), where rcssserver logs what
 * it received in that step. A player step whose counters go back or jump by more than one (the
 * steps a game log does not show, before kick-off) gets no entry; they are counted in
 * {@link #warnings()}, the first named.
 */
public final class InferredCommandLog implements CommandSource {
    /**
     * What one player executed in one step.
     *
     * @param staminaLeft the most a dash could spend: the stamina before it and the type's extra stamina
     */
    record PlayerStep(int time, int stoppage, String team, int unum, CommandInference.Step step, double staminaLeft) {
    }

    /** Receives the inferred steps in order. */
    @FunctionalInterface
    interface Listener {
        void step(PlayerStep step);
    }

    private final Path gameLog;
    private final List<CommandLogReader.Entry> entries;
    private final List<String> warnings;
    private final Iterator<CommandLogReader.Entry> next;

    private InferredCommandLog(Path gameLog, List<CommandLogReader.Entry> entries, List<String> warnings) {
        this.gameLog = gameLog;
        this.entries = entries;
        this.warnings = warnings;
        this.next = entries.iterator();
    }

    /** Reads the game log and infers its players' commands. */
    public static InferredCommandLog of(Path gameLog) throws IOException {
        List<CommandLogReader.Entry> entries = new ArrayList<>();
        Walk walk = new Walk(gameLog, step -> {
            String text = step.step().text();
            if (!text.isEmpty()) {
                entries.add(new CommandLogReader.Entry(0, step.time(), step.stoppage(), step.team(), step.unum(), text));
            }
        });
        List<String> warnings = walk.run();
        if (walk.first != null) {
            // a view only synchronous vision has: a client of version 18 or later (they see synchronously
            // from their init on); the game log does not tell the version, 18 is the first such
            int time = walk.first.time() == 0 ? 0 : walk.first.time() - 1;
            int stoppage = walk.first.time() == 0 ? -1 : 0;
            List<CommandLogReader.Entry> inits = new ArrayList<>();
            for (PlayerState player : walk.first.players()) {
                if (walk.synchronous.contains(Walk.slot(player))) {
                    String team = player.side() == Side.LEFT ? walk.first.leftTeam() : walk.first.rightTeam();
                    inits.add(new CommandLogReader.Entry(0, time, stoppage, team, player.unum(),
                            "(init " + team + " (version 18))"));
                }
            }
            entries.addAll(0, inits);
        }
        return new InferredCommandLog(gameLog, entries, warnings);
    }

    /** Player steps inferred. */
    public int size() {
        return entries.size();
    }

    /** What the counters did not tell, naming the game log and cycle. */
    public List<String> warnings() {
        return warnings;
    }

    /**
     * Infers every player's step of the game log in order, handing each to {@code listener}; returns
     * the warnings. A game log cut in its last line gives the steps up to there.
     */
    static List<String> infer(Path gameLog, Listener listener) throws IOException {
        return new Walk(gameLog, listener).run();
    }

    private static final class Walk {
        final Path gameLog;
        final Listener listener;
        final ServerModel model = new ServerModel();
        final List<String> warnings = new ArrayList<>();
        CommandInference inference;
        GameFrame first;
        GameFrame previous;
        int previousStoppage;
        final Map<Integer, PlayerState> before = new HashMap<>();
        /** The players seen with a view cone only synchronous vision has (two or four thirds of the visible angle). */
        final Set<Integer> synchronous = new HashSet<>();
        long irregular;
        String firstIrregular;

        Walk(Path gameLog, Listener listener) {
            this.gameLog = gameLog;
            this.listener = listener;
        }

        List<String> run() throws IOException {
            try {
                GameLogReader.forEach(gameLog, this::frame, model::parameters);
            } catch (GameLogException e) {
                if (!e.cutOff() || previous == null) {
                    throw e;
                }
                warnings.add(e.getMessage() + "; the game log is cut there: commands up to cycle " + previous.time()
                        + " inferred");
            }
            if (irregular > 0) {
                warnings.add(gameLog + ": " + irregular + " player steps without inferred commands: counters going"
                        + " back or jumping by more than one between two shows (steps the log does not show); the first "
                        + firstIrregular);
            }
            return warnings;
        }

        void frame(GameFrame frame) {
            if (inference == null) {
                inference = new CommandInference(model); // the parameters come before the first show
            }
            int stoppage = previous != null && previous.time() == frame.time() ? previousStoppage + 1 : 0;
            if (previous != null) {
                int ballMovers = 0;
                for (PlayerState b : frame.players()) {
                    PlayerState a = before.get(slot(b));
                    if (a != null && (b.counts().kick() > a.counts().kick() || b.counts().tackle() > a.counts().tackle())) {
                        ballMovers++;
                    }
                }
                for (PlayerState b : frame.players()) {
                    PlayerState a = before.get(slot(b));
                    if (a == null) {
                        continue;
                    }
                    CommandInference.Step step = inference.infer(previous, a, frame, b, ballMovers > 1);
                    String team = a.side() == Side.LEFT ? previous.leftTeam() : previous.rightTeam();
                    if (step.irregular() != null) {
                        if (irregular++ == 0) {
                            firstIrregular = "at cycle " + previous.time() + " for " + team + "_" + a.unum() + ": "
                                    + step.irregular();
                        }
                        continue;
                    }
                    listener.step(new PlayerStep(previous.time(), previousStoppage, team, a.unum(), step,
                            a.stamina() + model.type(a.type()).extraStamina()));
                }
            }
            before.clear();
            double visibleAngle = model.get("visible_angle", 90);
            for (PlayerState state : frame.players()) {
                before.put(slot(state), state);
                double factor = state.viewWidth() / visibleAngle;
                if (Math.abs(factor - 2.0 / 3) < 1e-6 || Math.abs(factor - 4.0 / 3) < 1e-6) {
                    synchronous.add(slot(state));
                }
            }
            first = first == null ? frame : first;
            previous = frame;
            previousStoppage = stoppage;
        }

        static int slot(PlayerState state) {
            return (state.side() == Side.LEFT ? 0 : 1000) + state.unum();
        }
    }

    @Override
    public CommandLogReader.Entry next() {
        return next.hasNext() ? next.next() : null;
    }

    @Override
    public Path file() {
        return gameLog;
    }

    @Override
    public void close() {
    }
}
