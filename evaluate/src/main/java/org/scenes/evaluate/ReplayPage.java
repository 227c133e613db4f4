package org.scenes.evaluate;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.scenes.api.Side;
import org.scenes.internal.files.AtomicOutput;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.PlayerState;

/**
 * A replay of one game in a web page that needs no network: the frames as JSON inside the page
 * and a small script drawing them on a canvas (pitch, players, ball, score, play mode), with a
 * cycle slider, play/pause and speed. Each team is drawn in the colour its name says where it
 * names one (Teal, Amber, Red ...), shown in a legend; players on the same spot get their numbers
 * side by side, and the player with the ball within kicking reach is ringed and named.
 */
public final class ReplayPage {
    private static final ObjectMapper JSON = new ObjectMapper();

    private ReplayPage() {
    }

    /** Writes a page holding only the replay, atomically. */
    public static void write(Path file, String title, List<GameFrame> frames) throws IOException {
        if (frames.isEmpty()) {
            throw new IllegalArgumentException("a replay needs at least one frame");
        }
        String html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + escape(title)
                + "</title>\n<style>\n" + style() + "</style>\n</head>\n<body>\n<h1>" + escape(title) + "</h1>\n"
                + section("replay", frames) + "<script>\n" + script() + "</script>\n</body>\n</html>\n";
        try (AtomicOutput output = AtomicOutput.create(file)) {
            output.stream().write(html.getBytes(StandardCharsets.UTF_8));
            output.commit();
        }
    }

    /** The replay's markup and data; the page needs {@link #script()} once after all replays. */
    static String section(String id, List<GameFrame> frames) {
        GameFrame last = frames.get(frames.size() - 1);
        String[] colours = colours(last.leftTeam(), last.rightTeam());
        return "<div class=\"replay\" id=\"" + escape(id) + "\">\n"
                + "<div class=\"replay-legend\">" + legendEntry(colours[0], last.leftTeam(), "left")
                + legendEntry(colours[1], last.rightTeam(), "right")
                + "<span><span class=\"ring\"></span>has the ball (within kicking reach)</span></div>\n"
                + "<canvas width=\"920\" height=\"624\"></canvas>\n<div class=\"replay-controls\">"
                + "<button class=\"replay-play\" type=\"button\">&#9654; play</button>"
                + "<input class=\"replay-cycle\" type=\"range\" min=\"0\" max=\"0\" value=\"0\" aria-label=\"frame\">"
                + "<select class=\"replay-speed\" aria-label=\"speed\"><option value=\"1\">x1</option>"
                + "<option value=\"4\" selected>x4</option><option value=\"10\">x10</option></select>"
                + "<span class=\"replay-status\"></span></div>\n"
                + "<script type=\"application/json\" class=\"replay-data\">" + data(frames) + "</script>\n</div>\n";
    }

    private static String legendEntry(String colour, String team, String side) {
        return "<span><span class=\"swatch\" style=\"background:" + colour + "\"></span>"
                + escape(team.isEmpty() ? "(no team)" : team) + " (" + side + ")</span>";
    }

    /** Team colours for names that are colours; the rest get amber and blue, never both the same. */
    private static final Map<String, String> NAMED_COLOURS = Map.ofEntries(
            Map.entry("teal", "#008080"), Map.entry("amber", "#ffbf00"), Map.entry("red", "#d62728"),
            Map.entry("blue", "#1f5fd6"), Map.entry("green", "#2ca02c"), Map.entry("yellow", "#f2e200"),
            Map.entry("orange", "#ff7f0e"), Map.entry("purple", "#8e44ad"), Map.entry("black", "#111111"),
            Map.entry("white", "#f4f4f4"), Map.entry("pink", "#f06aa8"), Map.entry("cyan", "#17becf"),
            Map.entry("brown", "#8c564b"), Map.entry("grey", "#888888"), Map.entry("gray", "#888888"));
    private static final List<String> FALLBACK_COLOURS = List.of("#ffbf00", "#1f5fd6", "#d62728");

    /** The left and right team's colours, as CSS hex: the colour a name starts with, if any. */
    static String[] colours(String left, String right) {
        String leftColour = NAMED_COLOURS.get(firstWord(left));
        String rightColour = NAMED_COLOURS.get(firstWord(right));
        for (String fallback : FALLBACK_COLOURS) {
            if (leftColour == null && !fallback.equals(rightColour)) {
                leftColour = fallback;
            } else if (rightColour == null && !fallback.equals(leftColour)) {
                rightColour = fallback;
            }
        }
        if (leftColour.equals(rightColour)) {
            // two teams named alike ("Teal" against "Teal_2"): the right one in the fallback that differs
            String taken = leftColour;
            rightColour = FALLBACK_COLOURS.stream().filter(c -> !c.equals(taken)).findFirst().orElseThrow();
        }
        return new String[] {leftColour, rightColour};
    }

    private static String firstWord(String team) {
        return team.toLowerCase(Locale.ROOT).split("[^a-z]", 2)[0];
    }

    static String style() {
        return "body{font-family:sans-serif;margin:1.5em;color:#222;max-width:1320px}"
                + ".replay canvas{border:1px solid #444;max-width:100%}"
                + ".replay-legend{display:flex;gap:1.6em;align-items:center;margin:.3em 0}"
                + ".replay-legend .swatch{display:inline-block;width:1em;height:1em;border:1px solid #111;"
                + "border-radius:50%;margin-right:.4em;vertical-align:-.15em}"
                + ".replay-legend .ring{display:inline-block;width:1em;height:1em;border:3px solid #fff;"
                + "outline:1px solid #111;border-radius:50%;margin-right:.4em;vertical-align:-.2em;background:#3a7d3a}"
                + ".replay-controls{display:flex;gap:.8em;align-items:center;margin:.4em 0 1.2em}"
                + ".replay-cycle{flex:1}.replay-status{font-family:monospace;min-width:24em}\n";
    }

    static String script() {
        try (InputStream in = ReplayPage.class.getResourceAsStream("replay.js")) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** The characters of small steps, step {@code -STEP_RANGE} first; replay.js holds the same. */
    static final String STEPS = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxy";
    static final int STEP_RANGE = 30;

    /**
     * The frames compactly, a track per number: team names, the play modes once, the players'
     * sides and numbers once, the frame count, the frames where the play mode or the score
     * changes ({@code [frame, mode index, score left, score right]}), and each track (the clock;
     * ball x and y; each player's x, y and body direction, in the order of the last frame's
     * players) as whole units (clock cycles, tenths of metres, degrees) written step by step,
     * and the owner track (1 + index of the player with the ball, 0 for none), the same way:
     * a step of -30 to 30 as one character of {@link #STEPS}, a larger one as {@code ~STEP;}. A
     * player missing from a frame stays where it was. Six thousand frames of ten players take
     * about 200 KB where a JSON array per frame took 1.2 MB.
     */
    static String data(List<GameFrame> frames) {
        // the last frame: every player that connected is in it
        GameFrame complete = frames.get(frames.size() - 1);
        List<String> keys = new ArrayList<>();
        List<List<Object>> players = new ArrayList<>();
        for (PlayerState p : complete.players()) {
            keys.add(key(p));
            players.add(List.of(p.side() == Side.LEFT ? "l" : "r", p.unum()));
        }
        Map<String, Integer> modeIndex = new LinkedHashMap<>();
        List<List<Integer>> events = new ArrayList<>();
        Track owner = new Track();
        Track time = new Track();
        Track ballX = new Track();
        Track ballY = new Track();
        List<Track[]> tracks = new ArrayList<>();
        for (int i = 0; i < keys.size(); i++) {
            tracks.add(new Track[] {new Track(), new Track(), new Track()});
        }
        long[] last = new long[3 * keys.size()];
        List<Integer> previous = null;
        for (int f = 0; f < frames.size(); f++) {
            GameFrame frame = frames.get(f);
            for (PlayerState p : frame.players()) {
                int i = keys.indexOf(key(p));
                if (i >= 0) {
                    last[3 * i] = tenths(p.x());
                    last[3 * i + 1] = tenths(p.y());
                    last[3 * i + 2] = Math.round(p.body());
                }
            }
            int mode = modeIndex.computeIfAbsent(frame.playMode(), m -> modeIndex.size());
            if (previous == null || previous.get(1) != mode || previous.get(2) != frame.scoreLeft()
                    || previous.get(3) != frame.scoreRight()) {
                previous = List.of(f, mode, frame.scoreLeft(), frame.scoreRight());
                events.add(previous);
            }
            owner.add(owner(frame, keys) + 1);
            time.add(frame.time());
            ballX.add(tenths(frame.ball().x()));
            ballY.add(tenths(frame.ball().y()));
            for (int i = 0; i < keys.size(); i++) {
                for (int k = 0; k < 3; k++) {
                    tracks.get(i)[k].add(last[3 * i + k]);
                }
            }
        }
        Map<String, Object> data = new LinkedHashMap<>();
        data.put("left", complete.leftTeam());
        data.put("right", complete.rightTeam());
        data.put("colours", List.of(colours(complete.leftTeam(), complete.rightTeam())));
        data.put("modes", new ArrayList<>(modeIndex.keySet()));
        data.put("players", players);
        data.put("frames", frames.size());
        data.put("events", events);
        data.put("time", time.toString());
        data.put("ball", List.of(ballX.toString(), ballY.toString()));
        // per frame, 1 + the index of the player with the ball, 0 for none
        data.put("owner", owner.toString());
        data.put("tracks", tracks.stream().map(t -> List.of(t[0].toString(), t[1].toString(), t[2].toString())).toList());
        try {
            // "</" cannot end the script element early: JSON allows the slash escaped
            return JSON.writeValueAsString(data).replace("</", "<\\/");
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * The reach within which a player has the ball: rcssserver's default player size, kickable
     * margin and ball size (0.3 + 0.7 + 0.085 m).
     */
    static final double KICKABLE = 1.085;

    /** The index in {@code keys} of the player nearest the ball within {@link #KICKABLE}, or -1. */
    static int owner(GameFrame frame, List<String> keys) {
        int owner = -1;
        double nearest = KICKABLE;
        for (PlayerState p : frame.players()) {
            double distance = Math.hypot(p.x() - frame.ball().x(), p.y() - frame.ball().y());
            if (distance <= nearest && keys.contains(key(p))) {
                nearest = distance;
                owner = keys.indexOf(key(p));
            }
        }
        return owner;
    }

    /** One track of whole numbers, written as its steps. */
    static final class Track {
        private final StringBuilder text = new StringBuilder();
        private long value;

        void add(long next) {
            long step = next - value;
            value = next;
            if (Math.abs(step) <= STEP_RANGE) {
                text.append(STEPS.charAt((int) step + STEP_RANGE));
            } else {
                text.append('~').append(step).append(';');
            }
        }

        @Override
        public String toString() {
            return text.toString();
        }
    }

    private static long tenths(double v) {
        return Math.round(v * 10);
    }

    private static String key(PlayerState p) {
        return p.side() + "_" + p.unum();
    }

    static String escape(String text) {
        return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}
