package org.scenes.internal.convert;

import java.io.IOException;
import java.io.InterruptedIOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import org.scenes.internal.convert.RebuildStep.Sent;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.PlayerState;

/**
 * Rebuilds and converts its players, step by step, on a thread of its own (or the caller's): for
 * each show, each player's {@code sense_body}, then its commands and sees of the coming step in
 * the order the player sent and got them, and checks its commands against what the show says was
 * executed.
 */
final class RebuildWorker implements Runnable {
    private final PerceptWriter percepts;
    private final GameParameters parameters;
    private final PlayerSlots slots;
    private final boolean commandsBeforeSee;
    private final BlockingQueue<RebuildStep> queue;
    private volatile Throwable failure;
    private Thread thread;

    RebuildWorker(PerceptWriter percepts, GameParameters parameters, PlayerSlots slots, boolean commandsBeforeSee,
                  boolean threaded) {
        this.percepts = percepts;
        this.parameters = parameters;
        this.slots = slots;
        this.commandsBeforeSee = commandsBeforeSee;
        this.queue = threaded ? new ArrayBlockingQueue<>(64) : null;
    }

    /** Starts the worker's own thread (a threaded worker only). */
    void start(String name) {
        thread = new Thread(this, name);
        thread.setDaemon(true);
        thread.start();
    }

    @Override
    public void run() {
        try {
            while (true) {
                RebuildStep step = queue.take();
                if (step == RebuildStep.END) {
                    return;
                }
                if (failure == null) {
                    process(step);
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (IOException | RuntimeException | Error e) {
            failure = e;
            queue.clear();
        }
    }

    void submit(RebuildStep step) throws IOException {
        if (queue == null) {
            process(step);
            return;
        }
        rethrow();
        try {
            queue.put(step);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new InterruptedIOException("interrupted");
        }
    }

    /** Ends the worker's thread once it has done the steps handed to it. */
    void stop() throws IOException {
        if (thread != null && thread.isAlive()) {
            try {
                queue.put(RebuildStep.END);
                thread.join();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new InterruptedIOException("interrupted");
            }
        }
    }

    void rethrow() throws IOException {
        Throwable e = failure;
        if (e instanceof IOException io) {
            throw io;
        } else if (e instanceof RuntimeException runtime) {
            throw runtime;
        } else if (e instanceof Error error) {
            throw error;
        }
    }

    private void process(RebuildStep step) throws IOException {
        GameFrame frame = step.frame();
        if (frame == null) {
            // what was sent after the last show
            for (Sent sent : step.before()) {
                if (sent.player().worker == this && sent.player().feed != null) {
                    percepts.deliver(sent.player(), sent.message());
                }
            }
            return;
        }
        for (RebuiltPlayer player : step.players()) {
            if (player.worker == this && player.feed == null) {
                percepts.start(player, frame);
            }
        }
        for (Sent sent : step.before()) {
            if (sent.player().worker == this) {
                percepts.deliver(sent.player(), sent.message());
                sent.player().commandStep = step.index();
            }
        }
        int time = frame.time();
        for (PlayerState state : frame.players()) {
            RebuiltPlayer player = slots.of(state);
            if (player == null || player.worker != this) {
                continue;
            }
            if (step.commandsCover()) {
                checkAgreement(player, state);
            }
            if (percepts.world()) {
                // the world model reads the player's own state and the referee's calls
                percepts.senseBody(player, state, time);
                percepts.referee(player, frame);
            } else {
                percepts.senseBody(player, time);
            }
            // this show's sees and commands belong to the next step
            long next = step.index() + 1;
            List<String> sent = sentBy(player, step);
            int first = commandsFirst(player, sent.size());
            deliver(player, sent.subList(0, first), next);
            if (step.seesDue()) {
                int sees = seesDue(player, state, step);
                for (int i = 0; i < sees; i++) {
                    percepts.see(player, state, frame);
                    player.seeStep = next;
                }
            }
            deliver(player, sent.subList(first, sent.size()), next);
        }
    }

    /**
     * How many of the player's {@code sent} commands of the coming step went out before its
     * see. The command log does not say. A player that already holds a see taken after its last
     * command took effect (a see of a later step than that command's) has what it needs and
     * answers it at the step's start, as Krislet does; one that does not waits for the step's
     * see; of several commands in a step, all but the last answered earlier sees. Synchronous
     * sees come with {@code sense_body}, so commands follow them.
     */
    private int commandsFirst(RebuiltPlayer player, int sent) {
        if (commandsBeforeSee) {
            return sent;
        }
        if (sent == 0 || player.synchSee) {
            return 0;
        }
        return player.seeStep > player.commandStep ? Math.max(1, sent - 1) : sent - 1;
    }

    private static List<String> sentBy(RebuiltPlayer player, RebuildStep step) {
        List<String> sent = List.of();
        for (Sent s : step.at()) {
            if (s.player() == player) {
                if (sent.isEmpty()) {
                    sent = new ArrayList<>(2);
                }
                sent.add(s.message());
            }
        }
        return sent;
    }

    private void deliver(RebuiltPlayer player, List<String> messages, long index) throws IOException {
        for (String message : messages) {
            percepts.deliver(player, message);
            player.commandStep = index;
        }
    }

    /**
     * The game log's counts of executed commands against the command log: a body command the
     * player sent in a step shows as a count rising by the next show. Another game's command log
     * disagrees in most steps.
     */
    private static void checkAgreement(RebuiltPlayer player, PlayerState state) {
        PlayerState.Counts c = state.counts();
        int executed = c.kick() + c.dash() + c.turn() + c.catches() + c.move() + c.tackle();
        if (player.executed >= 0) {
            if ((executed > player.executed) == player.sentBody) {
                player.agreed++;
            } else {
                player.disagreed++;
            }
        }
        player.executed = executed;
        player.sentBody = false;
    }

    /**
     * How many sees the player gets after this show: synchronous ones as the reading thread's
     * {@link SynchSeeCounter} decided, asynchronous ones by the player's see clock.
     */
    private int seesDue(RebuiltPlayer player, PlayerState state, RebuildStep step) {
        if (player.synchSee) {
            return step.synchSees().contains(player) ? 1 : 0;
        }
        // The show was written at the end of its step; its sees go out in the next step.
        return SeePhases.asynchSees(step.index() + 1, parameters.period(state), player.seeOffset,
                parameters.simulatorStep);
    }
}
