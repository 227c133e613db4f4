package org.scenes.evaluate;

import java.util.Objects;
import java.util.function.Consumer;
import java.util.function.IntFunction;
import org.scenes.api.ObjectKind;
import org.scenes.internal.protocol.CommandType;
import org.scenes.internal.protocol.InitReply;
import org.scenes.internal.protocol.Message;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.PlayerCommand;
import org.scenes.internal.protocol.See;
import org.scenes.internal.protocol.VisualObject;
import org.scenes.simulator.Brain;

/**
 * A brain that drives the player and, beside it, an optional shadow brain fed exactly the same
 * messages whose commands go nowhere: what the shadow would have done in the driver's place.
 * Both are traced see by see in a {@link PlayerTrace}. The shadow never shares the driver's
 * random source, so the driver plays exactly as it would alone.
 */
final class TracedBrain implements Brain {
    /** A player's trace and shadow brain (or none). */
    record Seat(PlayerTrace trace, Brain shadow) {
    }

    private final Brain driver;
    /** Makes the trace and shadow for the uniform number the server gives; null when they were given. */
    private final IntFunction<Seat> seats;
    private Brain shadow;
    private PlayerTrace trace;
    private final MessageParser parser = new MessageParser();
    private boolean paused = true;

    TracedBrain(Brain driver, Brain shadow, PlayerTrace trace) {
        this.driver = Objects.requireNonNull(driver, "driver");
        this.seats = null;
        this.shadow = shadow;
        this.trace = Objects.requireNonNull(trace, "trace");
    }

    /**
     * A driver whose trace and shadow are made when the server's answer to its init gives its
     * uniform number: on a live server the players' answers are handled on their own threads in
     * no fixed order, and a trace or shadow seed taken by arrival went to another number now and then.
     */
    TracedBrain(Brain driver, IntFunction<Seat> seats) {
        this.driver = Objects.requireNonNull(driver, "driver");
        this.seats = Objects.requireNonNull(seats, "seats");
    }

    /** The driver's: the runtime repeats kick-off moves only for a driver that wants them. */
    @Override
    public boolean repeatsKickOffMove() {
        return driver.repeatsKickOffMove();
    }

    @Override
    public void receive(String message, Consumer<String> send) {
        InitReply reply = trace == null ? PlayerNumber.given(parser, message) : null;
        if (reply != null) {
            Seat seat = seats.apply(reply.uniformNumber());
            trace = seat.trace();
            shadow = seat.shadow();
        }
        if (trace == null) {
            driver.receive(message, send); // nothing to trace before the player has its number
            return;
        }
        if (shadow instanceof LateShadow late) {
            late.collect(this::shadowSent); // the reply to what came before this message
        }
        if (message.startsWith("(see ")) {
            Message parsed = parser.parse(message);
            if (parsed instanceof See see) {
                trace.see(see.time(), viewKey(see), paused);
            }
        } else if (message.startsWith("(hear ") && message.contains(" referee ")) {
            paused = isPause(message.substring(message.indexOf(" referee ") + 9, message.length() - 1).trim());
        }
        driver.receive(message, command -> {
            send.accept(command);
            PlayerCommand body = body(command);
            if (body != null) {
                trace.driverSent(body);
            }
        });
        if (shadow != null) {
            shadow.receive(message, this::shadowSent);
        }
    }

    private void shadowSent(String command) {
        PlayerCommand body = body(command);
        if (body != null) {
            trace.shadowSent(body);
        }
    }

    /** The play modes in which the clock stands still and nothing a player does moves it. */
    static boolean isPause(String mode) {
        return mode.equals("before_kick_off") || mode.startsWith("goal_l") || mode.startsWith("goal_r")
                || mode.equals("half_time") || mode.equals("time_over");
    }

    private PlayerCommand body(String text) {
        Message message;
        try {
            message = parser.parse(text);
        } catch (RuntimeException e) {
            return null;
        }
        if (message instanceof PlayerCommand command && command.wellFormed()
                && (command.type() == CommandType.DASH || command.type() == CommandType.TURN
                    || command.type() == CommandType.KICK)) {
            return command;
        }
        return null;
    }

    /**
     * A key of what a see shows of the world that only the player and the ball can change: the
     * ball, flags, goals and lines with their distances and directions as sent (players are left
     * out: others moving do not unstick a player). Equal keys: the player saw the same thing.
     */
    static long viewKey(See see) {
        long key = 17;
        for (VisualObject object : see.objects()) {
            if (object.kind() == ObjectKind.PLAYER) {
                continue;
            }
            key = 31 * key + object.name().hashCode();
            key = 31 * key + Double.hashCode(object.distance());
            key = 31 * key + Double.hashCode(object.direction());
        }
        return key;
    }
}
