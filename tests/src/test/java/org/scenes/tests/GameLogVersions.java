package org.scenes.tests;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonGenerator;
import java.io.IOException;
import java.io.Writer;
import java.math.BigDecimal;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.GameLogReader;
import org.scenes.internal.gamelog.PlayerState;

/**
 * A game log of the simulator (version 6) rewritten in the other forms rcssserver writes, for
 * tests of what reads them: text versions 4 (stamina without capacity) and 5 (no focus point),
 * and the JSON array of {@code game_log_version -1} (numbers as read, not rounded to the text
 * forms' four decimals). Frames and parameters are the same; only the form changes.
 */
final class GameLogVersions {
    private static final Pattern PARAMETER = Pattern.compile("\\((\\w+) (\"[^\"]*\"|[^()\\s]+)\\)");

    private GameLogVersions() {
    }

    /** {@code source} rewritten as version 4 or 5 ({@code "4"}, {@code "5"}) or JSON ({@code "json"}) at {@code target}. */
    static Path rewrite(Path source, String version, Path target) throws IOException {
        List<GameFrame> frames = new ArrayList<>();
        List<String> parameters = new ArrayList<>();
        GameLogReader.forEach(source, frames::add, parameters::add);
        try (Writer out = Files.newBufferedWriter(target, StandardCharsets.UTF_8)) {
            if (version.equals("json")) {
                json(out, parameters, frames);
            } else {
                text(out, Integer.parseInt(version), parameters, frames);
            }
        }
        return target;
    }

    private static void text(Writer out, int version, List<String> parameters, List<GameFrame> frames)
            throws IOException {
        out.write("ULG" + version + "\n");
        for (String line : parameters) {
            out.write(line + "\n");
        }
        GameFrame previous = null;
        for (GameFrame frame : frames) {
            if (previous == null || !previous.playMode().equals(frame.playMode())) {
                out.write("(playmode " + frame.time() + " " + frame.playMode() + ")\n");
            }
            if (previous == null || previous.scoreLeft() != frame.scoreLeft() || previous.scoreRight() != frame.scoreRight()
                    || !previous.leftTeam().equals(frame.leftTeam())) {
                out.write("(team " + frame.time() + " " + name(frame.leftTeam()) + " " + name(frame.rightTeam()) + " "
                        + frame.scoreLeft() + " " + frame.scoreRight() + ")\n");
            }
            StringBuilder show = new StringBuilder("(show ").append(frame.time()).append(" ((b) ")
                    .append(join(frame.ball().x(), frame.ball().y(), frame.ball().vx(), frame.ball().vy())).append(')');
            for (PlayerState p : frame.players()) {
                show.append(" ((").append(p.side().letter()).append(' ').append(p.unum()).append(") ").append(p.type())
                        .append(" 0x").append(Integer.toHexString(p.state())).append(' ')
                        .append(join(p.x(), p.y(), p.vx(), p.vy(), p.body(), p.neck()))
                        .append(" (v ").append(p.viewQuality()).append(' ').append(plain(p.viewWidth())).append(")")
                        .append(" (s ").append(join(p.stamina(), p.effort(), p.recovery()));
                if (version >= 5) {
                    show.append(' ').append(Double.isNaN(p.capacity()) ? "-1" : plain(p.capacity()));
                }
                PlayerState.Counts c = p.counts();
                show.append(") (c ").append(c.kick()).append(' ').append(c.dash()).append(' ').append(c.turn())
                        .append(' ').append(c.catches()).append(' ').append(c.move()).append(' ').append(c.turnNeck())
                        .append(' ').append(c.changeView()).append(' ').append(c.say()).append(' ').append(c.tackle())
                        .append(' ').append(c.pointto()).append(' ').append(c.attentionto()).append("))");
            }
            out.write(show.append(")\n").toString());
            previous = frame;
        }
    }

    private static void json(Writer out, List<String> parameters, List<GameFrame> frames) throws IOException {
        try (JsonGenerator json = new JsonFactory().createGenerator(out)) {
            json.writeStartArray();
            json.writeStartObject();
            json.writeStringField("version", "19.0.0");
            json.writeEndObject();
            for (String line : parameters) {
                json.writeStartObject();
                json.writeObjectFieldStart(line.substring(1, line.indexOf(' ')));
                Matcher m = PARAMETER.matcher(line);
                while (m.find()) {
                    String value = m.group(2);
                    if (value.startsWith("\"")) {
                        json.writeStringField(m.group(1), value.substring(1, value.length() - 1));
                    } else {
                        json.writeFieldName(m.group(1));
                        json.writeNumber(new BigDecimal(value));
                    }
                }
                json.writeEndObject();
                json.writeEndObject();
            }
            GameFrame previous = null;
            for (GameFrame frame : frames) {
                if (previous == null || !previous.playMode().equals(frame.playMode())) {
                    json.writeStartObject();
                    json.writeObjectFieldStart("playmode");
                    json.writeNumberField("time", frame.time());
                    json.writeStringField("mode", frame.playMode());
                    json.writeEndObject();
                    json.writeEndObject();
                }
                json.writeStartObject();
                json.writeObjectFieldStart("team");
                json.writeNumberField("time", frame.time());
                team(json, "l", frame.leftTeam(), frame.scoreLeft());
                team(json, "r", frame.rightTeam(), frame.scoreRight());
                json.writeEndObject();
                json.writeEndObject();
                show(json, frame);
                previous = frame;
            }
            json.writeEndArray();
        }
    }

    private static void team(JsonGenerator json, String side, String name, int score) throws IOException {
        json.writeObjectFieldStart(side);
        json.writeStringField("name", name);
        json.writeNumberField("score", score);
        json.writeEndObject();
    }

    private static void show(JsonGenerator json, GameFrame frame) throws IOException {
        json.writeStartObject();
        json.writeObjectFieldStart("show");
        json.writeNumberField("time", frame.time());
        json.writeObjectFieldStart("ball");
        json.writeNumberField("x", frame.ball().x());
        json.writeNumberField("y", frame.ball().y());
        json.writeNumberField("vx", frame.ball().vx());
        json.writeNumberField("vy", frame.ball().vy());
        json.writeEndObject();
        json.writeArrayFieldStart("players");
        for (PlayerState p : frame.players()) {
            json.writeStartObject();
            json.writeStringField("side", String.valueOf(p.side().letter()));
            json.writeNumberField("unum", p.unum());
            json.writeNumberField("type", p.type());
            json.writeNumberField("state", p.state());
            json.writeNumberField("x", p.x());
            json.writeNumberField("y", p.y());
            json.writeNumberField("vx", p.vx());
            json.writeNumberField("vy", p.vy());
            json.writeNumberField("body", p.body());
            json.writeNumberField("neck", p.neck());
            json.writeStringField("vq", String.valueOf(p.viewQuality()));
            json.writeNumberField("vw", p.viewWidth());
            json.writeNumberField("stamina", p.stamina());
            json.writeNumberField("effort", p.effort());
            json.writeNumberField("recovery", p.recovery());
            json.writeNumberField("capacity", Double.isNaN(p.capacity()) ? -1 : p.capacity());
            PlayerState.Counts c = p.counts();
            json.writeNumberField("kick", c.kick());
            json.writeNumberField("dash", c.dash());
            json.writeNumberField("turn", c.turn());
            json.writeNumberField("catch", c.catches());
            json.writeNumberField("move", c.move());
            json.writeNumberField("turn_neck", c.turnNeck());
            json.writeNumberField("change_view", c.changeView());
            json.writeNumberField("say", c.say());
            json.writeNumberField("tackle", c.tackle());
            json.writeNumberField("pointto", c.pointto());
            json.writeNumberField("attentionto", c.attentionto());
            json.writeEndObject();
        }
        json.writeEndArray();
        json.writeEndObject();
        json.writeEndObject();
    }

    private static String name(String team) {
        return team.isEmpty() ? "null" : team;
    }

    private static String join(double... values) {
        StringBuilder text = new StringBuilder();
        for (double value : values) {
            text.append(text.length() == 0 ? "" : " ").append(plain(value));
        }
        return text.toString();
    }

    private static String plain(double value) {
        return BigDecimal.valueOf(value).stripTrailingZeros().toPlainString();
    }
}
