package org.scenes.internal.convert;

import java.io.IOException;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.scenes.internal.convert.RebuildStep.Sent;
import org.scenes.internal.gamelog.CommandLogReader;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.PlayerState;
import org.scenes.internal.protocol.MessageParser;

/**
 * When asynchronous sees fall: where each player's see clock starts (its phase, see
 * {@link GameLogConverter.SeePhase}), told by the timing of its commands read ahead, or else by
 * what it did in its first cycles, the steps held meanwhile.
 */
final class SeePhases {
    /** Cycles of a player's commands read ahead to infer the phase of its see clock. */
    private static final int PHASE_WINDOW = 300;
    /**
     * Cycles of what a player did that decide its see clock when the timing of its commands did not
     * (measured on three real-server games of the project's Krislet: 17 of 18 right from 300 cycles,
     * all 18 from 600); the steps are held meanwhile.
     */
    private static final int CONTENT_WINDOW = 1000;
    /** Commands more that another phase must explain, as a share of those read, to replace the first step's. */
    private static final double PHASE_MARGIN = 0.1;
    /** Steps of the candidate phases, in ms. */
    private static final double PHASE_GRAIN = 2.5;

    /**
     * Where an asynchronous player's see clock may start: the likeliest offset, the candidates, and
     * whether the timing of its commands told them apart.
     */
    record Phase(double offset, List<Double> candidates, boolean told) {
        /** The first step's clock, nothing to decide. */
        static final Phase FIRST_STEP = new Phase(0, List.of(0.0), true);
    }

    /** A player whose see clock waits for what it did in its first cycles, from {@code from} on. */
    private record Undecided(RebuiltPlayer player, int from, List<Double> candidates) {
    }

    private final GameLogConverter.SeePhase seePhase;
    private final CommandsAhead commands;
    private final StepClock clock;
    private final GameParameters parameters;
    private final PlayerSlots slots;
    private final MessageParser parser = new MessageParser();
    /** The server's step of each player's init, by TEAM_UNUM. */
    private final Map<String, Long> initSteps = new HashMap<>();
    /** Players whose see clocks their commands' timing did not tell, and the steps held meanwhile. */
    private final List<Undecided> undecided = new ArrayList<>();
    private final ArrayDeque<RebuildStep> held = new ArrayDeque<>();

    SeePhases(GameLogConverter.SeePhase seePhase, CommandsAhead commands, StepClock clock, GameParameters parameters,
              PlayerSlots slots) {
        this.seePhase = seePhase;
        this.commands = commands;
        this.clock = clock;
        this.parameters = parameters;
        this.slots = slots;
    }

    /** The player's init arrived in the server's step {@code at}. */
    void init(String key, long at) {
        initSteps.put(key, at);
    }

    /**
     * The phase of an asynchronous player's see clock, in ms from the first step's start: of the
     * {@link #candidates}, the one whose sees fall in the steps of most of the player's commands
     * of the next {@link #PHASE_WINDOW} cycles (up to its first {@code change_view}); the first
     * unless another explains clearly more. When every candidate explains about as many (a
     * player on a clock of its own), the timing has not told, and what the player did decides
     * ({@link #byContent}). A command logged in a cycle belongs to the step after that cycle's
     * show, the step its see is sent in.
     */
    Phase phase(String key, int time, PlayerState state) throws IOException {
        if (seePhase == GameLogConverter.SeePhase.FIRST_STEP) {
            return Phase.FIRST_STEP;
        }
        commands.readThrough(time + PHASE_WINDOW);
        long shift = clock.step() - time + 1;
        // the stoppage steps of the cycles passed (a goal, half time) shift the later ones
        int cycle = time;
        int cycleStoppage = 0;
        List<Long> steps = new ArrayList<>();
        for (CommandLogReader.Entry entry : commands.entries()) {
            if (entry.time() >= time + PHASE_WINDOW) {
                break;
            }
            if (entry.time() < time) {
                continue;
            }
            if (entry.time() != cycle) {
                shift += cycleStoppage;
                cycle = entry.time();
                cycleStoppage = 0;
            }
            if (entry.referee()) {
                continue; // the kick-off after a goal is logged past the cycle's last step
            }
            cycleStoppage = Math.max(cycleStoppage, entry.stoppage());
            if (!key.equals(entry.team() + "_" + entry.unum()) || entry.text().startsWith("(init ")) {
                continue;
            }
            if (entry.text().contains("(change_view ")) {
                break;
            }
            steps.add(entry.time() + entry.stoppage() + shift);
        }
        double period = parameters.period(state);
        List<Double> candidates = candidates(initSteps.get(key), period);
        double first = candidates.get(0);
        double bestOffset = first;
        int firstScore = explained(steps, period, first);
        int best = firstScore;
        int worst = firstScore;
        for (double offset : candidates.subList(1, candidates.size())) {
            int score = explained(steps, period, offset);
            worst = Math.min(worst, score);
            if (score > best) {
                best = score;
                bestOffset = offset;
            }
        }
        double margin = PHASE_MARGIN * steps.size();
        // every candidate explains the commands alike: a player on a clock of its own
        boolean told = best - worst > margin;
        return new Phase(best - firstScore > margin ? bestOffset : first, candidates, told);
    }

    /**
     * The offsets the player's see clock may have, the likeliest first. With its init's step known
     * (rcssserver's command log counts the steps before kick-off as stoppage), its counter's
     * first tick is the first {@code send_step / 4} tick after the init arrived, any time in
     * that step: one of the 3 or 4 ticks from the step's start to a tick past its end; its first
     * see comes {@code interval} ticks on; the first tick is taken unless commands tell otherwise.
     * Without it (or at step 0, as the project's simulator logs every init), any offset in
     * {@link #PHASE_GRAIN} ms steps, 0 first.
     */
    private List<Double> candidates(Long initStep, double period) {
        List<Double> offsets = new ArrayList<>();
        if (initStep == null || initStep == 0) {
            for (double offset = 0; offset < period - 1e-9; offset += PHASE_GRAIN) {
                offsets.add(offset);
            }
            return offsets;
        }
        double simulatorStep = parameters.simulatorStep;
        double tick = parameters.sendStep / 4;
        long interval = Math.max(1, Math.round(period / tick));
        double from = initStep * simulatorStep;
        double until = from + simulatorStep + tick;
        for (long t = (long) Math.floor(from / tick + 1e-9) + 1; t * tick < until - 1e-9; t++) {
            // the server's step g sends the sees of the cycle it makes: this converter's step g - shift + 1
            double see = (t + interval - 1) * tick - (clock.serverShift() - 1) * simulatorStep;
            offsets.add(((see % period) + period) % period);
        }
        return offsets;
    }

    private int explained(List<Long> steps, double period, double offset) {
        int count = 0;
        for (long s : steps) {
            if (asynchSees(s, period, offset, parameters.simulatorStep) > 0) {
                count++;
            }
        }
        return count;
    }

    /** The player's phase was not told: what it does from cycle {@code from} on decides it. */
    void undecided(RebuiltPlayer player, int from, Phase phase) {
        undecided.add(new Undecided(player, from, phase.candidates()));
    }

    /** Hands a step to the workers, or holds it while a player's see clock is undecided. */
    void hand(RebuildStep work, RebuildWorkers workers) throws IOException {
        if (undecided.isEmpty() && held.isEmpty()) {
            workers.submit(work);
            return;
        }
        held.add(work);
        decide(work.frame().time(), workers);
    }

    /**
     * Sets the see clocks of the undecided players whose first {@link #CONTENT_WINDOW} cycles were
     * read by {@code time}; once none is left, hands out the steps held.
     */
    void decide(int time, RebuildWorkers workers) throws IOException {
        undecided.removeIf(u -> {
            if (u.from() + CONTENT_WINDOW > time) {
                return false;
            }
            u.player().seeOffset = byContent(u);
            return true;
        });
        if (undecided.isEmpty()) {
            while (!held.isEmpty()) {
                workers.submit(held.pollFirst());
            }
        }
    }

    /**
     * Of the undecided player's candidate clocks, the one whose sees best explain what it did in
     * the steps held (see {@link PhaseEvidence}); the first when none explains more.
     */
    private double byContent(Undecided u) {
        RebuiltPlayer player = u.player();
        PhaseEvidence evidence = new PhaseEvidence(u.candidates(), parameters.simulatorStep,
                parameters.visibleDistance);
        for (RebuildStep step : held) {
            for (Sent sent : step.before()) {
                if (sent.player() == player) {
                    evidence.command(BodyCommands.first(parser, sent.message()));
                }
            }
            for (PlayerState state : step.frame().players()) {
                if (slots.of(state) == player) {
                    GameFrame.BallState ball = step.frame().ball();
                    // the show's sees go out in the next step, before or with its commands
                    evidence.show(step.index() + 1, parameters.period(state), state, ball.x(), ball.y());
                }
            }
            for (Sent sent : step.at()) {
                if (sent.player() == player) {
                    evidence.command(BodyCommands.first(parser, sent.message()));
                }
            }
        }
        return u.candidates().get(evidence.best());
    }

    /**
     * How many asynchronous sees fall in step {@code step}: those at {@code offset} plus multiples
     * of {@code period} (ms) from the first step's start.
     */
    static int asynchSees(long step, double period, double offset, double simulatorStep) {
        double begin = step * simulatorStep - offset;
        double end = begin + simulatorStep;
        double first = Math.ceil(begin / period - 1e-9) * period;
        return first < end - 1e-9 ? (int) Math.floor((end - 1e-9 - first) / period) + 1 : 0;
    }
}
