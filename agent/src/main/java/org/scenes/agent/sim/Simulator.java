package org.scenes.agent.sim;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.function.Consumer;
import java.util.function.IntConsumer;
import org.scenes.agent.Brain;
import org.scenes.gamelog.GameFrame;
import org.scenes.gamelog.PlayerState;
import org.scenes.protocol.CommandType;
import org.scenes.protocol.Message;
import org.scenes.protocol.MessageParser;
import org.scenes.protocol.PlayerCommand;
import org.scenes.protocol.ProtocolException;
import org.scenes.scene.Side;

/**
 * An embedded soccer server: plays one game between in-process brains that exchange version 9
 * protocol text with it, synchronously, step by step (100 ms of game time each): every step each
 * player gets {@code sense_body}, the referee's announcements and, on two steps of three (a
 * {@code see} every 150 ms), {@code see}; then the commands the brains sent are executed (one
 * world-changing command per player and step), the world moves and the referee judges.
 * Everything random comes from the setup's seed, so a game repeats byte for byte.
 */
public final class Simulator {
    private final GameSetup setup;
    private final ServerParams params = ServerParams.DEFAULT;
    private final World world;
    private final Physics physics;
    private final Vision vision;
    private final Referee referee;
    private final MessageParser parser = new MessageParser();
    private final List<Client> clients = new ArrayList<>();
    private int kicksLeft;
    private int kicksRight;

    public Simulator(GameSetup setup) {
        this.setup = setup;
        this.world = new World(params, setup.seed());
        this.physics = new Physics(world);
        this.vision = new Vision(world);
        this.referee = new Referee(world, setup.cycles());
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
        try {
            connect(setup.left(), Side.LEFT);
            connect(setup.right(), Side.RIGHT);
            frames.accept(frame());
            int steps = play(progress, frames);
            List<Path> logs = new ArrayList<>();
            for (Client client : clients) {
                if (client.log() != null) {
                    logs.add(client.log().commit());
                }
            }
            return new GameResult(world.scoreLeft, world.scoreRight, kicksLeft, kicksRight, world.time, steps, logs);
        } catch (UncheckedIOException e) {
            throw e.getCause();
        } finally {
            for (Client client : clients) {
                if (client.log() != null) {
                    client.log().close();
                }
            }
        }
    }

    private void connect(GameSetup.Team team, Side side) throws IOException {
        for (int unum = 1; unum <= team.players(); unum++) {
            // Each brain gets its own random source derived from the game seed and its seat.
            Random random = new Random(setup.seed() * 1_000_003L + (side == Side.LEFT ? 0 : 100) + unum);
            Brain brain = team.brains().create(team.name(), random);
            Player player = world.add(team.name(), side, unum);
            PlayerLog log = setup.logDirectory() == null ? null
                    : new PlayerLog(setup.logDirectory().resolve(team.name() + "_" + unum + ".lsf.gz"));
            Client client = new Client(player, brain, log);
            clients.add(client);
            client.sentByClient("(init " + team.name() + " (version 9))");
            client.deliver(Vision.initReply(player, "before_kick_off"));
            client.deliver(params.serverParamMessage());
            client.deliver(params.playerParamMessage());
            client.deliver(params.playerTypeMessage());
            // The real server executes commands as they arrive before kick-off, such as the first move.
            execute(client);
        }
    }

    private int play(IntConsumer progress, Consumer<GameFrame> frames) {
        List<String> announcements = List.of();
        int step = 0;
        while (true) {
            // A see every send_step (150 ms) while steps are simulator_step (100 ms): two steps of three.
            long nextSee = ((long) step * params.simulatorStep() + params.sendStep() - 1) / params.sendStep()
                    * params.sendStep();
            boolean see = nextSee < (long) (step + 1) * params.simulatorStep();
            for (Client client : clients) {
                client.deliver(vision.senseBody(client.player));
                for (String announcement : announcements) {
                    client.deliver(announcement);
                }
                if (see && world.mode != PlayMode.TIME_OVER) {
                    client.deliver(vision.see(client.player));
                }
            }
            step++;
            if (world.mode == PlayMode.TIME_OVER) {
                return step;
            }
            for (Client client : clients) {
                execute(client);
            }
            if (world.mode.clockRuns) {
                physics.step();
            }
            for (Client client : clients) {
                physics.recover(client.player);
                client.player.acted = false;
            }
            referee.endStep();
            announcements = referee.takeAnnouncements();
            frames.accept(frame());
            progress.accept(world.time);
        }
    }

    /** Executes what the client sent: the first world-changing command of the step, and neck turns. */
    private void execute(Client client) {
        Player player = client.player;
        List<String> commands = List.copyOf(client.sent);
        client.sent.clear(); // answers to errors below are the next step's commands
        for (String text : commands) {
            Message message;
            try {
                message = parser.parse(text);
            } catch (ProtocolException e) {
                client.deliver("(error illegal_command_form)");
                continue;
            }
            if (!(message instanceof PlayerCommand command)) {
                client.deliver("(error unknown_command)");
                continue;
            }
            if (!command.wellFormed()) {
                client.deliver("(error illegal_command_form)");
                continue;
            }
            CommandType type = command.type();
            if (type == CommandType.TURN_NECK) {
                physics.turnNeck(player, command.first());
                continue;
            }
            if (player.acted || !isBodyCommand(type)) {
                continue; // the server executes one body command per cycle; say, change_view etc. do nothing here
            }
            player.acted = true;
            switch (type) {
                case DASH -> physics.dash(player, command.first());
                case TURN -> physics.turn(player, command.first());
                case MOVE -> {
                    if (world.mode.allowsMove()) {
                        physics.move(player, command.first(), command.second());
                    }
                }
                case KICK -> {
                    if (referee.mayKick(player) && physics.kick(player, command.first(), command.second())) {
                        if (player.side == Side.LEFT) {
                            kicksLeft++;
                        } else {
                            kicksRight++;
                        }
                        referee.ballKicked(player);
                    }
                }
                default -> {
                }
            }
        }
    }

    /** The world as a game log records it now. */
    private GameFrame frame() {
        List<PlayerState> players = new ArrayList<>(clients.size());
        for (Client client : clients) {
            Player p = client.player;
            players.add(new PlayerState(p.side, p.unum, 0, PlayerState.STANDING, p.x, p.y, p.vx, p.vy, p.body,
                    p.neck, 'h', 90, p.stamina, p.effort, p.recovery, Double.NaN,
                    new PlayerState.Counts(p.kicks, p.dashes, p.turns, 0, p.moves, p.turnNecks, 0, 0, 0, 0, 0)));
        }
        return new GameFrame(world.time, referee.playModeWord(), setup.left().name(), setup.right().name(),
                world.scoreLeft, world.scoreRight,
                new GameFrame.BallState(world.ball.x, world.ball.y, world.ball.vx, world.ball.vy), players);
    }

    private static boolean isBodyCommand(CommandType type) {
        return type == CommandType.DASH || type == CommandType.TURN || type == CommandType.MOVE
                || type == CommandType.KICK;
    }
}
