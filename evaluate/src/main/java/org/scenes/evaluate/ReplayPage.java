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
import java.util.Map;
import org.scenes.api.Side;
import org.scenes.internal.files.AtomicOutput;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.PlayerState;

/**
 * A replay of one game in a web page that needs no network: the frames as JSON inside the page
 * and a small script drawing them on a canvas (pitch, players, ball, score, play mode), with a
 * cycle slider, play/pause and speed.
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
        return "<div class=\"replay\" id=\"" + escape(id) + "\">\n"
                + "<canvas width=\"920\" height=\"624\"></canvas>\n<div class=\"replay-controls\">"
                + "<button class=\"replay-play\" type=\"button\">&#9654; play</button>"
                + "<input class=\"replay-cycle\" type=\"range\" min=\"0\" max=\"0\" value=\"0\" aria-label=\"frame\">"
                + "<select class=\"replay-speed\" aria-label=\"speed\"><option value=\"1\">x1</option>"
                + "<option value=\"4\" selected>x4</option><option value=\"10\">x10</option></select>"
                + "<span class=\"replay-status\"></span></div>\n"
                + "<script type=\"application/json\" class=\"replay-data\">" + data(frames) + "</script>\n</div>\n";
    }

    static String style() {
        return "body{font-family:sans-serif;margin:1.5em;color:#222;max-width:1320px}"
                + ".replay canvas{border:1px solid #444;max-width:100%}"
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
     * players) as whole units (clock cycles, tenths of metres, degrees) written step by step:
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
        data.put("modes", new ArrayList<>(modeIndex.keySet()));
        data.put("players", players);
        data.put("frames", frames.size());
        data.put("events", events);
        data.put("time", time.toString());
        data.put("ball", List.of(ballX.toString(), ballY.toString()));
        data.put("tracks", tracks.stream().map(t -> List.of(t[0].toString(), t[1].toString(), t[2].toString())).toList());
        try {
            // "</" cannot end the script element early: JSON allows the slash escaped
            return JSON.writeValueAsString(data).replace("</", "<\\/");
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
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
