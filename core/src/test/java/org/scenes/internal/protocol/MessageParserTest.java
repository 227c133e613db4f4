package org.scenes.internal.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.scenes.api.ObjectKind;
import org.scenes.api.Side;

class MessageParserTest {
    private final MessageParser parser = new MessageParser();

    private See see(String text) {
        See see = assertInstanceOf(See.class, parser.parse(text));
        assertEquals(List.of(), see.leftovers(), "leftovers of " + text);
        return see;
    }

    private VisualObject only(String objectText) {
        See see = see("(see 12 " + objectText + ")");
        assertEquals(1, see.objects().size());
        return see.objects().get(0);
    }

    @Test
    void aQuoteInALandmarksNameIsNoNameAndNeverRunsOffTheMessage() {
        // found by fuzzing: the balance check reads a string from the quote, the name reader read on
        // past it, and an unclosed list later ran it off the end (ArrayIndexOutOfBoundsException)
        See see = assertInstanceOf(See.class, parser.parse(
                "(see 5 ((f \") 1 2) ((g r) 50 -10) ((P) 0.6 -83 ((p \"Opp\" 1 goalie) 11 2) ((l r) 54.1 79))"));
        assertEquals(List.of("l r"), see.objects().stream().map(VisualObject::name).toList());
        assertEquals(1, see.leftovers().size(), "what could not be read is kept as leftovers: " + see.leftovers());
        // nor is a lone quote taken into a flag's name
        See lone = assertInstanceOf(See.class,
                parser.parse("(see 5 ((f \") 1 2) ((g r) 50 -10) ((p \"Opp\" 1) 11 2) ((l r) 54.1 79))"));
        assertTrue(lone.objects().stream().noneMatch(o -> o.name().contains("\"")), lone.toString());
    }

    @Test
    void seeKeepsTimeAndObjectsInServerOrder() {
        See see = see("(see 37 ((f r b) 37.3 13) ((b) 2.7 -5 -0.1 3.2) ((l r) 36.2 90))");
        assertEquals(37, see.time());
        assertEquals(List.of("f r b", "b", "l r"), see.objects().stream().map(VisualObject::name).toList());
        VisualObject ball = see.objects().get(1);
        assertEquals(ObjectKind.BALL, ball.kind());
        assertEquals(2.7, ball.distance());
        assertEquals(-5, ball.direction());
        assertEquals(-0.1, ball.distanceChange());
        assertEquals(3.2, ball.directionChange());
        assertTrue(Double.isNaN(ball.bodyFacing()));
    }

    @Test
    void emptySeeHasNoObjects() {
        assertEquals(List.of(), see("(see 264)").objects());
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "((ball) 8.2 0)|BALL|b",
        "((b) 8.2 0)|BALL|b",
        "((goal r) 60.3 0)|GOAL|g r",
        "((g l) 60.3 0)|GOAL|g l",
        "((flag c t) 4.3 45)|FLAG|f c t",
        "((f p r b) 48.4 25)|FLAG|f p r b",
        "((flag t r 10) 13.2 -8)|FLAG|f t r 10",
        "((line b) 63.4 -33)|LINE|l b",
        "((l b) 63.4 -33)|LINE|l b",
        "((B) 2.1 160)|BALL|B",
        "((Ball) 2.1 160)|BALL|B",
        "((F) 2.1 160)|FLAG|F",
        "((Flag) 2.1 160)|FLAG|F",
        "((G) 2.1 160)|GOAL|G",
        "((P) 3 -117)|PLAYER|P",
        "((Player) 3 -117)|PLAYER|P",
    })
    void namesLongShortAndUpperCase(String object, ObjectKind kind, String name) {
        VisualObject parsed = only(object);
        assertEquals(kind, parsed.kind());
        assertEquals(name, parsed.name());
        assertEquals(Character.isUpperCase(name.charAt(0)), parsed.behind());
    }

    @Test
    void playersInEveryForm() {
        VisualObject full = only("((p \"Carleton\" 3) 10.5 -20 0.4 -1 45 50)");
        assertEquals("p", full.name());
        assertEquals("Carleton", full.team());
        assertEquals(3, full.uniformNumber());
        assertFalse(full.goalie());
        assertEquals(10.5, full.distance());
        assertEquals(-20, full.direction());
        assertEquals(0.4, full.distanceChange());
        assertEquals(-1, full.directionChange());
        assertEquals(45, full.bodyFacing());
        assertEquals(50, full.headFacing());
        assertTrue(Double.isNaN(full.pointingDirection()));
        assertEquals(' ', full.mark());

        VisualObject pointing = only("((p \"Opp\" 1 goalie) 6 0 0 0 -33 -33 12 t)");
        assertTrue(pointing.goalie());
        assertEquals(12, pointing.pointingDirection());
        assertEquals('t', pointing.mark());

        VisualObject kicked = only("((p \"TestTeam\" 2) 7.4 0 0 0 0 0 k)");
        assertEquals('k', kicked.mark());
        assertTrue(Double.isNaN(kicked.pointingDirection()));

        VisualObject teamOnly = only("((p \"Carleton\") 36.6 -13)");
        assertEquals("Carleton", teamOnly.team());
        assertEquals(0, teamOnly.uniformNumber());
        assertTrue(Double.isNaN(teamOnly.distanceChange()));

        VisualObject farPointing = only("((p) 60.3 -28 40)");
        assertEquals("", farPointing.team());
        assertEquals(60.3, farPointing.distance());
        assertEquals(40, farPointing.pointingDirection());

        VisualObject longName = only("((player Opp 1) 18.2 9 0 0 0 0)");
        assertEquals("Opp", longName.team());
        assertEquals(1, longName.uniformNumber());

        VisualObject lowQuality = only("((p \"Opp\" 1 goalie) -23)");
        assertTrue(Double.isNaN(lowQuality.distance()));
        assertEquals(-23, lowQuality.direction());
    }

    @Test
    void quotedTeamNamesMayHoldSpacesAndParentheses() {
        VisualObject player = only("((p \"Big (Blue) Team\" 9) 5 5)");
        assertEquals("Big (Blue) Team", player.team());
        assertEquals(9, player.uniformNumber());
    }

    @Test
    void objectsOfUnknownShapeAreKeptAsLeftovers() {
        See see = assertInstanceOf(See.class, parser.parse("(see 3 ((x y) 1 2) ((b) 1 2 3) ((b) 4 5))"));
        assertEquals(1, see.objects().size());
        assertEquals(List.of("((x y) 1 2)", "((b) 1 2 3)"), see.leftovers());
    }

    @Test
    void senseBodyOfVersion19IsFullyUnderstood() {
        SenseBody body = assertInstanceOf(SenseBody.class, parser.parse("(sense_body 41 (view_mode high normal)"
                + " (stamina 7985.5 1 130600) (speed 0.33 -12) (head_angle 30) (kick 1) (dash 40) (turn 7) (say 2)"
                + " (turn_neck 3) (catch 0) (move 1) (change_view 4) (change_focus 0) (arm (movable 0) (expires 0)"
                + " (target 0 0) (count 1)) (focus (target none) (count 0)) (tackle (expires 0) (count 0))"
                + " (collision (ball) (player)) (foul (charged 0) (card none)) (focus_point 0 0))"));
        assertEquals(41, body.time());
        assertEquals("high", body.viewQuality());
        assertEquals("normal", body.viewWidth());
        assertEquals(7985.5, body.stamina());
        assertEquals(1, body.effort());
        assertEquals(130600, body.capacity());
        assertEquals(0.33, body.speed());
        assertEquals(-12, body.speedDirection());
        assertEquals(30, body.headAngle());
        assertEquals(new SenseBody.Counts(1, 40, 7, 2, 3, 0, 1, 4, 0), body.counts());
        assertEquals("0 0", body.details().get("arm.target"));
        assertEquals("none", body.details().get("foul.card"));
        assertEquals("(ball) (player)", body.details().get("collision"));
        assertEquals(List.of(), body.leftovers());
    }

    @Test
    void unknownSenseBodyPartsAreLeftovers() {
        SenseBody body = assertInstanceOf(SenseBody.class,
                parser.parse("(sense_body 0 (view_mode high normal) (stamina 8000 1) (speed 0) (wings 2))"));
        assertEquals(List.of("(wings 2)"), body.leftovers());
        assertTrue(Double.isNaN(body.speedDirection()));
        assertEquals(-1, body.counts().dash(), "not sent");
        SenseBody twice = assertInstanceOf(SenseBody.class,
                parser.parse("(sense_body 0 (collision none) (collision (ball)) (kick x))"));
        assertEquals(java.util.Map.of("collision", "(ball)"), twice.details());
        assertEquals(List.of("(kick x)"), twice.leftovers());
        assertEquals(-1, twice.counts().kick(), "a counter that is not a count is not taken");
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "(hear 0 referee kick_off_l)|REFEREE|NaN|0|kick_off_l",
        "(hear 0 self \"hello_p1\")|SELF|NaN|0|hello_p1",
        "(hear 0 self hello_p1)|SELF|NaN|0|hello_p1",
        "(hear 21 coach \"trainer_msg\")|COACH|NaN|0|trainer_msg",
        "(hear 0 -86 our 2 \"hi_p2\")|TEAMMATE|-86|2|hi_p2",
        "(hear 0 -19 opp \"hi_opp\")|OPPONENT|-19|0|hi_opp",
        "(hear 0 0 \"hi_p2\")|PLAYER|0|0|hi_p2",
        "(hear 14 -32 p2_t)|PLAYER|-32|0|p2_t",
        "(hear 7 our 4)|TEAMMATE|NaN|4|''",
        "(hear 7 opp)|OPPONENT|NaN|0|''",
    })
    void hearInEveryForm(String text, Hear.Speaker speaker, double direction, int unum, String said) {
        Hear hear = assertInstanceOf(Hear.class, parser.parse(text));
        assertEquals(speaker, hear.speaker());
        assertEquals(direction, hear.direction());
        assertEquals(unum, hear.uniformNumber());
        assertEquals(said, hear.text());
    }

    @Test
    void initFromClientAndServer() {
        InitRequest request = assertInstanceOf(InitRequest.class, parser.parse("(init Carleton (version 9))"));
        assertEquals(new InitRequest("Carleton", 9, false), request);
        assertTrue(request.fromClient());
        assertEquals(new InitRequest("Keepers", 3, true), parser.parse("(init Keepers (goalie))"));
        assertEquals(new InitReply("init", Side.RIGHT, 1, "before_kick_off"), parser.parse("(init r 1 before_kick_off)"));
        assertEquals(new InitReply("reconnect", Side.LEFT, 0, "play_on"), parser.parse("(reconnect l play_on)"));
        assertThrows(ProtocolException.class, () -> parser.parse("(init)"));
    }

    @Test
    void coachAndTrainerInitAndClientReconnect() {
        assertEquals(new InitReply("init", Side.LEFT, 0, null, InitReply.Role.COACH), parser.parse("(init l ok)"));
        assertEquals(new InitReply("init", null, 0, null, InitReply.Role.TRAINER), parser.parse("(init ok)"));
        assertEquals(InitReply.Role.PLAYER, ((InitReply) parser.parse("(init l 3 before_kick_off)")).role());
        InitRequest trainer = assertInstanceOf(InitRequest.class, parser.parse("(init (version 7))"));
        assertEquals(new InitRequest(null, 7, false), trainer);
        ReconnectRequest reconnect = assertInstanceOf(ReconnectRequest.class, parser.parse("(reconnect Carleton 4)"));
        assertEquals(new ReconnectRequest("Carleton", 4), reconnect);
        assertTrue(reconnect.fromClient());
        assertThrows(ProtocolException.class, () -> parser.parse("(reconnect Carleton)"));
        assertThrows(ProtocolException.class, () -> parser.parse("(reconnect Carleton four)"));
    }

    @Test
    void parametersNamedAndPositional() {
        Parameters named = assertInstanceOf(Parameters.class, parser.parse(
                "(server_param (audio_cut_dist 50)(game_log_dir \"./\")(ball_decay 0.94))"));
        assertEquals("server_param", named.head());
        assertEquals("./", named.named().get("game_log_dir"));
        assertEquals(0.94, named.number("ball_decay"));
        assertEquals(List.of("audio_cut_dist", "game_log_dir", "ball_decay"), List.copyOf(named.named().keySet()));
        Parameters positional = assertInstanceOf(Parameters.class, parser.parse("(player_type 0 1.05 45 0.4)"));
        assertEquals(List.of("0", "1.05", "45", "0.4"), positional.positional());
    }

    @Test
    void serverNotices() {
        assertEquals(new ServerNotice("error", "illegal_command_form"), parser.parse("(error illegal_command_form)"));
        assertEquals(new ServerNotice("warning", "message_not_null_terminated"),
                parser.parse("(warning message_not_null_terminated)"));
        assertEquals(new ServerNotice("ok", "synch_see"), parser.parse("(ok synch_see)"));
        assertEquals(new ServerNotice("think", ""), parser.parse("(think)"));
        assertEquals(new Score(40, 4, 0), parser.parse("(score 40 4 0)"));
        assertEquals(new ChangePlayerType(2, 1), parser.parse("(change_player_type 2 1)"));
        assertEquals(new ChangePlayerType(5, -1), parser.parse("(change_player_type 5)"));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "(dash 50)|DASH|50|NaN|''|true",
        "(dash 80 -90)|DASH|80|-90|''|true",
        "(dash)|DASH|NaN|NaN|''|false",
        "(dash fast)|DASH|NaN|NaN|''|false",
        "(turn -30.0)|TURN|-30|NaN|''|true",
        "(kick 100 0)|KICK|100|0|''|true",
        "(kick 100)|KICK|100|NaN|''|false",
        "(turn_neck 30)|TURN_NECK|30|NaN|''|true",
        "(catch 0)|CATCH|0|NaN|''|true",
        "(move -49.82603887211406 28.928989867299553)|MOVE|-49.82603887211406|28.928989867299553|''|true",
        "(tackle 30)|TACKLE|30|NaN|''|true",
        "(tackle 30 true)|TACKLE|30|NaN|true|true",
        "(say hello_p1)|SAY|NaN|NaN|hello_p1|true",
        "(say \"hi there\")|SAY|NaN|NaN|hi there|true",
        "(change_view wide high)|CHANGE_VIEW|NaN|NaN|wide high|true",
        "(sense_body)|SENSE_BODY|NaN|NaN|''|true",
        "(score)|SCORE|NaN|NaN|''|true",
        "(bye)|BYE|NaN|NaN|''|true",
        "(pointto 10 20)|POINTTO|10|20|''|true",
        "(pointto off)|POINTTO|NaN|NaN|off|true",
        "(attentionto our 2)|ATTENTIONTO|2|NaN|our 2|true",
        "(attentionto off)|ATTENTIONTO|NaN|NaN|off|true",
        "(change_focus 5 10)|CHANGE_FOCUS|5|10|''|true",
        "(gaussian_see)|GAUSSIAN_SEE|NaN|NaN|''|true",
        "(synch_see)|SYNCH_SEE|NaN|NaN|''|true",
        "(done)|DONE|NaN|NaN|''|true",
        "(ear (on our complete))|EAR|NaN|NaN|(on our complete)|true",
        "(compression 1)|COMPRESSION|1|NaN|''|true",
    })
    void everyPlayerCommand(String text, CommandType type, double first, double second, String words, boolean wellFormed) {
        PlayerCommand command = assertInstanceOf(PlayerCommand.class, parser.parse(text));
        assertEquals(type, command.type());
        assertEquals(first, command.first());
        assertEquals(second, command.second());
        assertEquals(words, command.text());
        assertEquals(wellFormed, command.wellFormed());
        assertTrue(command.fromClient());
        assertEquals(wellFormed && type.action() != org.scenes.api.ActionType.NONE, command.toAction() != null);
    }

    @Test
    void unknownHeadsAreKeptNotFatal() {
        assertEquals(new Unknown("foo", "(foo 1)"), parser.parse("(foo 1)"));
        assertEquals(new Unknown("change_mode", "(change_mode play_on)"), parser.parse("(change_mode play_on)"));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "(see 0 ((b) 1 2)|1 unclosed",
        "(see 0 ((b) 1 2)))|text after",
        "see 0|starts with '('",
        "'   '|empty message",
        "(see 0 ((p \"Carleton) 1 2))|string not closed",
        "(see zero)|an integer",
        "()|starts with its name",
    })
    void malformedMessagesAreErrorsWithColumn(String text, String problem) {
        ProtocolException error = assertThrows(ProtocolException.class, () -> parser.parse(text));
        assertTrue(error.getMessage().contains(problem), error.getMessage());
        assertTrue(error.column() >= 1);
    }

    @Test
    void trailingNulPaddingAndNewlinesAreIgnored() {
        byte[] padded = new byte[4096];
        byte[] text = "(dash 600)\n".getBytes(StandardCharsets.US_ASCII);
        System.arraycopy(text, 0, padded, 0, text.length);
        PlayerCommand dash = assertInstanceOf(PlayerCommand.class, parser.parse(padded, 0, padded.length));
        assertEquals(600, dash.first());
    }

    @Test
    void numbersAreExactlyWhatJavaParses() {
        Random random = new Random(7);
        for (int i = 0; i < 20000; i++) {
            String number = switch (i % 4) {
                case 0 -> Integer.toString(random.nextInt(2000) - 1000);
                case 1 -> String.format(java.util.Locale.ROOT, "%.1f", random.nextDouble() * 200 - 100);
                case 2 -> Double.toString(random.nextDouble() * 1e3 - 500);
                default -> String.format(java.util.Locale.ROOT, "%.6f", random.nextDouble() * 0.01);
            };
            PlayerCommand turn = (PlayerCommand) parser.parse("(turn " + number + ")");
            assertEquals(Double.parseDouble(number), turn.first(), number);
        }
        assertEquals(-0.0, ((PlayerCommand) parser.parse("(turn -0)")).first());
        assertEquals(1.5e-3, ((PlayerCommand) parser.parse("(turn 1.5e-3)")).first());
        assertFalse(((PlayerCommand) parser.parse("(turn 1.2.3)")).wellFormed());
    }
}
