package org.scenes.simulator;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.function.Consumer;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.PlayerState;
import org.scenes.internal.protocol.CommandType;
import org.scenes.internal.protocol.Message;
import org.scenes.internal.protocol.MessageParser;
import org.scenes.internal.protocol.PlayerCommand;
import org.scenes.internal.protocol.ProtocolException;

/**
 * The simulator as a stepping engine, whoever its clients are: players {@linkplain #join join}
 * and get their init reply and parameters ({@link #welcome}); what they send is
 * {@linkplain #received queued}; each step is {@link #sense} (every player gets
 * {@code sense_body}, the referee's announcements and, when due, {@code see}) and then
 * {@link #advance} (the queued commands are executed, one world-changing command per player and
 * step, the world moves, the referee judges). The in-process {@link Simulator} and the UDP
 * server drive the same engine, so the same commands give the same game. Not thread-safe: one
 * thread drives it.
 */
public final class Engine {
    /** A client the server does not seat: {@link #answer()} is rcssserver's error message for it. */
    public static final class Refused extends Exception {
        private final String answer;

        Refused(String answer) {
            super(answer);
            this.answer = answer;
        }

        public String answer() {
            return answer;
        }
    }

    private final ServerParams params = ServerParams.DEFAULT;
    private final int cycles;
    private final World world;
    private final Physics physics;
    private final Vision vision;
    private final Referee referee;
    private final MessageParser parser = new MessageParser();
    private final List<Seat> seats = new ArrayList<>();
    private final String[] teams = new String[2];
    private GameRecorder recorder;
    private List<String> announcements = List.of();
    private int step;
    /**
     * Steps that sent senses so far: the game's and, in real time, those while the server waits
     * for the teams ({@link #waitingStep}); the sees' clock, so their rhythm runs on into the game.
     */
    private int sensings;
    /** Whether {@link #sense} ran for the step not yet {@link #advance}d (what arrives now is logged with its time). */
    private boolean sensed;
    private int stoppage;
    private int kicksLeft;
    private int kicksRight;
    private boolean over;

    public Engine(int cycles, long seed) {
        if (cycles < 1) {
            throw new IllegalArgumentException("cycles must be at least 1, not " + cycles);
        }
        this.cycles = cycles;
        this.world = new World(params, seed);
        this.physics = new Physics(world);
        this.vision = new Vision(world);
        this.referee = new Referee(world, cycles, physics);
    }

    /** Records the game ({@code .rcg} and {@code .rcl}) from now on. */
    public void record(GameRecorder gameRecorder) {
        this.recorder = gameRecorder;
    }

    /**
     * A new player of {@code team}: the first team to join plays on the left, the second on the
     * right; it gets the lowest free uniform number. Refused, with the server's answers, when a
     * third team asks ({@code no_more_team}), or the team is full or has its goalie
     * ({@code no_more_player_or_goalie_or_illegal_client_version}). {@code init} is the client's
     * message as received, for the command log.
     */
    public Seat join(String team, int version, boolean goalie, String init, Consumer<String> out) throws Refused {
        Side side;
        if (team.equals(teams[0]) || teams[0] == null) {
            side = Side.LEFT;
        } else if (team.equals(teams[1]) || teams[1] == null) {
            side = Side.RIGHT;
        } else {
            throw new Refused("(error no_more_team)");
        }
        int unum = 0;
        for (int candidate = 1; candidate <= GameSetup.MAX_PLAYERS && unum == 0; candidate++) {
            unum = taken(side, candidate) ? 0 : candidate;
        }
        if (unum == 0 || goalie && seats.stream().anyMatch(s -> s.side() == side && s.goalie() && s.connected)) {
            throw new Refused("(error no_more_player_or_goalie_or_illegal_client_version)");
        }
        teams[side == Side.LEFT ? 0 : 1] = team;
        Seat seat = new Seat(world.add(team, side, unum, goalie), version, out);
        seat.seeCountFrom = loggedStep() + 1;
        seats.add(seat);
        seats.sort(Comparator.comparing(Seat::side).thenComparingInt(Seat::unum));
        log(seat, init);
        return seat;
    }

    private boolean taken(Side side, int unum) {
        return seats.stream().anyMatch(s -> s.side() == side && s.unum() == unum);
    }

    /**
     * A client takes over a player of its team ({@code (reconnect TEAM UNUM)}): the player comes
     * back if it had left, and messages go to {@code out} from now on. Refused during play on
     * ({@code cannot_reconnect_while_playon}) and for an unknown team or number
     * ({@code no_such_team_or_player}).
     */
    public Seat rejoin(String team, int unum, String reconnect, Consumer<String> out) throws Refused {
        if (world.mode == PlayMode.PLAY_ON) {
            throw new Refused("(error cannot_reconnect_while_playon)");
        }
        for (Seat seat : seats) {
            if (seat.team().equals(team) && seat.unum() == unum) {
                if (!seat.connected) {
                    world.players.add(seat.player);
                    world.players.sort(World.ORDER);
                    seat.connected = true;
                }
                seat.out = out;
                seat.pending.clear();
                log(seat, reconnect);
                seat.send("(reconnect " + seat.side().letter() + ' ' + referee.playModeWord() + ')');
                sendParameters(seat);
                return seat;
            }
        }
        throw new Refused("(error no_such_team_or_player)");
    }

    /** The connected player of that side and number, or null. */
    public Seat seat(Side side, int unum) {
        for (Seat seat : seats) {
            if (seat.side() == side && seat.unum() == unum && seat.connected) {
                return seat;
            }
        }
        return null;
    }

    /**
     * The init reply, then {@code server_param}, {@code player_param} and the player type, in the
     * seat's version; for version 18 and later then {@code (ok synch_see)}: rcssserver gives those
     * clients synchronous sees from their init on, and the game's logs are converted so.
     */
    public void welcome(Seat seat) {
        seat.send(Vision.initReply(seat.player, referee.playModeWord()));
        sendParameters(seat);
        if (seat.version >= 18) {
            synchSee(seat);
        }
    }

    /** Synchronous sees from now on, their counter from the next step (also for a repeated request). */
    private void synchSee(Seat seat) {
        if (!seat.player.synchSee) {
            seat.seeCount = 0;
            seat.seeCountFrom = loggedStep() + 1;
        }
        seat.player.synchSee = true;
        seat.player.highQuality = true;
        seat.send("(ok synch_see)");
    }

    private void sendParameters(Seat seat) {
        if (seat.version < 8) {
            seat.send(params.serverParamMessageV7(cycles / 2, Referee.DROP_BALL_TIME));
            seat.send(params.playerParamMessageV7());
            seat.send(params.playerTypeMessageV7());
        } else {
            seat.send(params.serverParamMessage());
            seat.send(params.playerParamMessage());
            seat.send(params.playerTypeMessage());
        }
    }

    /** What the client sent: logged, and executed at the end of the step (or by {@link #executePending}). */
    public void received(Seat seat, String command) {
        log(seat, command);
        seat.pending.add(command);
    }

    /** A message the server handles itself, such as {@code (done)}: only logged. */
    public void note(Seat seat, String message) {
        log(seat, message);
    }

    /** Takes the player out of the game ({@code bye}, or dropped for silence): it leaves the pitch. */
    public void leave(Seat seat, String bye) {
        if (!seat.connected) {
            return;
        }
        if (bye != null) {
            log(seat, bye);
        }
        seat.connected = false;
        seat.pending.clear();
        world.remove(seat.player);
    }

    /** The connected players, left team first, by number. */
    public List<Seat> seats() {
        return seats.stream().filter(s -> s.connected).toList();
    }

    /** Whether the game has reached {@code time_over} and the last messages were sent. */
    public boolean over() {
        return over;
    }

    public int time() {
        return world.time;
    }

    /** Steps begun so far, including pauses with the clock stopped. */
    public int steps() {
        return step;
    }

    public int scoreLeft() {
        return world.scoreLeft;
    }

    public int scoreRight() {
        return world.scoreRight;
    }

    public int kicksLeft() {
        return kicksLeft;
    }

    public int kicksRight() {
        return kicksRight;
    }

    /** The team on a side, null while none joined. */
    public String team(Side side) {
        return teams[side == Side.LEFT ? 0 : 1];
    }

    /**
     * While the server waits for the teams: a {@code sense_body} for every player, the clock at
     * 0, nothing else changes (clients that take a long silence for a lost server stay).
     */
    public void keepAlive() {
        for (Seat seat : seats()) {
            seat.send(vision.senseBody(seat.player, seat.version));
        }
    }

    /**
     * The first half of a step: each player gets {@code sense_body}, the referee's announcements
     * of the previous step and the sees due in this step. Returns false (and the game is over)
     * when this was the step of {@code time_over}, which gets no see.
     */
    public boolean sense() {
        for (Seat seat : seats()) {
            seat.send(vision.senseBody(seat.player, seat.version));
            for (String announcement : announcements) {
                seat.send(announcement);
            }
            if (world.mode != PlayMode.TIME_OVER) {
                sendSees(seat);
            }
        }
        step++;
        sensings++;
        sensed = true;
        if (world.mode == PlayMode.TIME_OVER) {
            over = true;
            return false;
        }
        return true;
    }

    /**
     * A step of real time while the server waits for the teams, as rcssserver's cycles run
     * from its start on: the clock stays at 0 and nothing moves; every player gets
     * {@code sense_body} and the sees due, and may send a body command again (the server
     * executes what arrives now at once, through {@link #executePending}: the kick-off move, a
     * turn). Not a step of the game: {@link #steps} does not count it. The synchronous server
     * has none, so its games stay as they were.
     */
    public void waitingStep() {
        for (Seat seat : seats()) {
            seat.player.acted = false;
            physics.recover(seat.player);
            seat.send(vision.senseBody(seat.player, seat.version));
            sendSees(seat);
        }
        sensings++;
        sensed = true;
    }

    /** The sees due to the seat in the step now sensed. */
    private void sendSees(Seat seat) {
        // A see every send_step (150 ms in normal view, scaled by the view width and halved in low
        // quality) while steps are simulator_step (100 ms): as many as multiples of the period in the step.
        long begin = (long) sensings * params.simulatorStep();
        int sees = seesDue(seat, begin, begin + params.simulatorStep());
        for (int i = 0; i < sees; i++) {
            seat.send(vision.see(seat.player));
        }
    }

    private int seesDue(Seat seat, long begin, long end) {
        Player player = seat.player;
        if (player.synchSee) {
            // Version 18+ synchronous sees, at the cycle's start, as rcssserver counts them: the seat's
            // counter rises once a step from the step after its connection (or synch_see) and a see goes
            // out when it reaches the width's interval (1, 2, 3 for narrow, normal, wide), then from 0;
            // change_view sets the interval, not the counter, so the server's logs tell which steps see.
            if (sensings < seat.seeCountFrom) {
                return 0;
            }
            int every = player.viewWidth == Player.ViewWidth.NARROW ? 1 : player.viewWidth == Player.ViewWidth.NORMAL
                    ? 2 : 3;
            if (++seat.seeCount < every) {
                return 0;
            }
            seat.seeCount = 0;
            return 1;
        }
        long period = Math.round(params.sendStep() * player.viewWidth.factor * (player.highQuality ? 1 : 0.5));
        long first = (begin + period - 1) / period * period;
        return first < end ? (int) ((end - 1 - first) / period + 1) : 0;
    }

    /**
     * The second half of a step: the queued commands are executed, the world moves when the
     * clock runs, stamina recovers, the referee judges and the clock advances.
     */
    public GameFrame advance() {
        for (Seat seat : seats()) {
            executePending(seat);
        }
        if (world.mode.objectsMove) {
            physics.step();
        }
        for (Seat seat : seats()) {
            physics.recover(seat.player);
            seat.player.acted = false;
            if (seat.catchBan > 0) {
                seat.catchBan--;
            }
        }
        int before = world.time;
        referee.endStep();
        sensed = false;
        stoppage = world.time == before ? stoppage + 1 : 0;
        announcements = referee.takeAnnouncements();
        recordAnnouncements();
        GameFrame frame = frame();
        if (recorder != null) {
            recorder.frame(frame);
        }
        return frame;
    }

    private void recordAnnouncements() {
        if (recorder == null) {
            return;
        }
        for (String announcement : announcements) {
            // (hear TIME referee WORD)
            String word = announcement.substring(announcement.lastIndexOf(' ') + 1, announcement.length() - 1);
            try {
                recorder.referee(world.time, stoppage, word);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
    }

    /**
     * Executes what the seat sent: the first world-changing command of the step, and neck turns,
     * view changes and the like. The real server executes commands as they arrive before
     * kick-off, such as the first move; a client's connection does that through this method.
     */
    public void executePending(Seat seat) {
        List<String> commands = List.copyOf(seat.pending);
        seat.pending.clear(); // answers to errors below are the next step's commands
        for (String text : commands) {
            Datagram datagram = datagram(text);
            for (Message message : datagram.messages()) {
                execute(seat, message);
            }
            if (datagram.malformed()) {
                seat.send("(error illegal_command_form)");
            }
        }
    }

    /** The commands of one datagram, up to a malformed one if any. */
    private record Datagram(List<Message> messages, boolean malformed) {
    }

    /**
     * A datagram may hold several commands, as librcsc sends them ({@code (turn 0)(change_view wide)(done)});
     * like the server, the commands before a malformed one count and the rest are rejected.
     */
    private Datagram datagram(String text) {
        List<Message> messages = new ArrayList<>(2);
        byte[] bytes = text.getBytes(StandardCharsets.UTF_8);
        try {
            parser.parseAll(bytes, 0, bytes.length, messages::add);
            return new Datagram(messages, false);
        } catch (ProtocolException e) {
            return new Datagram(messages, true);
        }
    }

    /**
     * Whether the datagram holds {@code (done)}, alone or after other commands: a synchronous
     * client has finished its cycle.
     */
    public boolean holdsDone(String text) {
        return datagram(text).messages().stream()
                .anyMatch(m -> m instanceof PlayerCommand command && command.type() == CommandType.DONE);
    }

    /** One command of a datagram: errors answered as the server answers them. */
    private void execute(Seat seat, Message message) {
        Player player = seat.player;
        if (!(message instanceof PlayerCommand command)) {
            // The server's command parser fails on what it does not know.
            seat.send("(error illegal_command_form)");
            return;
        }
        if (!command.wellFormed()) {
            seat.send("(error illegal_command_form)");
            return;
        }
        CommandType type = command.type();
        if (type == CommandType.TURN_NECK) {
            physics.turnNeck(player, command.first());
            return;
        }
        if (type == CommandType.CHANGE_VIEW) {
            changeView(seat, command.text());
            return;
        }
        if (type == CommandType.SAY) {
            player.says++;
            return;
        }
        if (player.acted || !isBodyCommand(type)) {
            return; // (done) too; the server executes one body command per cycle; pointto etc. do nothing here
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
            case CATCH -> goalieCatch(seat, command.first());
            default -> {
            }
        }
    }

    /**
     * Answers at once what the server answers on arrival rather than at the step's end:
     * {@code (score)}, {@code (sense_body)}, and {@code (synch_see)} of version 18+ clients.
     * Returns whether the message was one of them (it is logged); else the caller queues it
     * with {@link #received}.
     */
    public boolean answerNow(Seat seat, String text) {
        String trimmed = text.strip();
        int nul = trimmed.indexOf('\0');
        if (nul >= 0) {
            trimmed = trimmed.substring(0, nul).strip();
        }
        switch (trimmed) {
            case "(synch_see)" -> {
                log(seat, text);
                if (seat.version < 18) {
                    seat.send("(error illegal_command_form)");
                } else {
                    synchSee(seat);
                }
                return true;
            }
            case "(score)" -> {
                log(seat, text);
                boolean left = seat.side() == Side.LEFT;
                seat.send("(score " + world.time + ' ' + (left ? world.scoreLeft : world.scoreRight) + ' '
                        + (left ? world.scoreRight : world.scoreLeft) + ')');
                return true;
            }
            case "(sense_body)" -> {
                log(seat, text);
                seat.send(vision.senseBody(seat.player, seat.version));
                return true;
            }
            default -> {
                return false;
            }
        }
    }

    /** {@code (change_view WIDTH [QUALITY])}: the quality stays high when not given. */
    private void changeView(Seat seat, String arguments) {
        String[] words = arguments.split("\\s+");
        Player.ViewWidth width = Player.ViewWidth.of(words[0]);
        boolean quality = true;
        if (words.length == 2) {
            if (!words[1].equals("high") && !words[1].equals("low")) {
                seat.send("(error illegal_command_form)");
                return;
            }
            quality = words[1].equals("high");
        }
        if (width == null) {
            seat.send("(error illegal_command_form)");
            return;
        }
        if (seat.player.synchSee && !quality) {
            return; // synchronous sees are always of high quality: the server ignores the change
        }
        seat.player.viewWidth = width;
        seat.player.highQuality = quality;
        seat.player.changeViews++;
    }

    /**
     * A goalie's catch towards {@code direction} (relative to the body): it succeeds in play on,
     * from within the own penalty area, when the ball lies in the catchable area (a rectangle
     * catchable_area_l long and catchable_area_w wide in that direction), at most once every
     * catch_ban_cycle cycles.
     */
    private void goalieCatch(Seat seat, double direction) {
        Player goalie = seat.player;
        if (!goalie.goalie || seat.catchBan > 0 || world.mode != PlayMode.PLAY_ON) {
            return;
        }
        goalie.catches++;
        seat.catchBan = ServerParams.CATCH_BAN_CYCLE;
        double ownGoalX = goalie.side == Side.LEFT ? -ServerParams.PITCH_HALF_LENGTH : ServerParams.PITCH_HALF_LENGTH;
        boolean inPenaltyArea = Math.abs(goalie.x - ownGoalX) <= PENALTY_AREA_LENGTH
                && Math.abs(goalie.y) <= PENALTY_AREA_HALF_WIDTH;
        if (!inPenaltyArea) {
            return;
        }
        double angle = Math.toRadians(goalie.body + Physics.clamp(direction, params.minMoment(), params.maxMoment()));
        double dx = world.ball.x - goalie.x;
        double dy = world.ball.y - goalie.y;
        double along = dx * Math.cos(angle) + dy * Math.sin(angle);
        double across = -dx * Math.sin(angle) + dy * Math.cos(angle);
        if (along < 0 || along > ServerParams.CATCHABLE_AREA_L || Math.abs(across) > ServerParams.CATCHABLE_AREA_W / 2) {
            return;
        }
        world.ball.vx = 0;
        world.ball.vy = 0;
        world.ball.ax = 0;
        world.ball.ay = 0;
        referee.caught(goalie);
    }

    static final double PENALTY_AREA_LENGTH = 16.5;
    static final double PENALTY_AREA_HALF_WIDTH = 20.16;

    /** The world as a game log records it now. */
    public GameFrame frame() {
        List<PlayerState> players = new ArrayList<>(world.players.size());
        for (Player p : world.players) {
            int state = PlayerState.STANDING | (p.goalie ? PlayerState.GOALIE : 0);
            players.add(new PlayerState(p.side, p.unum, 0, state, p.x, p.y, p.vx, p.vy, p.body, p.neck,
                    p.highQuality ? 'h' : 'l', params.visibleAngle() * p.coneFactor(), p.stamina, p.effort,
                    p.recovery, Double.NaN, new PlayerState.Counts(p.kicks, p.dashes, p.turns, p.catches, p.moves,
                    p.turnNecks, p.changeViews, p.says, 0, 0, 0)));
        }
        return new GameFrame(world.time, referee.playModeWord(), teams[0] == null ? "" : teams[0],
                teams[1] == null ? "" : teams[1], world.scoreLeft, world.scoreRight,
                new GameFrame.BallState(world.ball.x, world.ball.y, world.ball.vx, world.ball.vy), players);
    }

    /** The server's parameter messages as a game log holds them (the newest version's form). */
    public List<String> parameterMessages() {
        return List.of(params.serverParamMessage(), params.playerParamMessage(), params.playerTypeMessage());
    }

    /** The step of the time the command log gives what arrives now. */
    private int loggedStep() {
        return sensed ? sensings - 1 : sensings;
    }

    private void log(Seat seat, String message) {
        if (recorder == null) {
            return;
        }
        try {
            recorder.received(world.time, stoppage, seat.team(), seat.unum(), message);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static boolean isBodyCommand(CommandType type) {
        return type == CommandType.DASH || type == CommandType.TURN || type == CommandType.MOVE
                || type == CommandType.KICK || type == CommandType.CATCH;
    }
}
