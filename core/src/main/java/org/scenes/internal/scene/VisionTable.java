package org.scenes.internal.scene;

import org.scenes.api.Cell;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;

/**
 * Renders a scene as a text "visiontable": one table row per distance ring (far at the top,
 * as the player would draw its view) and one column per angle slice (left to right), each
 * cell counting what lies in it: {@code B} ball, {@code G} goal, {@code nP} players,
 * {@code nF} flags, {@code nL} lines; then the actions with their parameters.
 */
public final class VisionTable {
    private static final ObjectKind[] ORDER = {ObjectKind.BALL, ObjectKind.GOAL, ObjectKind.PLAYER,
            ObjectKind.FLAG, ObjectKind.LINE};
    private static final char[] LETTERS = {'B', 'G', 'P', 'F', 'L'};

    private VisionTable() {
    }

    public static String render(Scene scene, Grid grid) {
        int columns = grid.columns();
        int rows = grid.rows();
        int[][][] counts = new int[rows][columns][ORDER.length];
        int teammates = 0;
        int opponents = 0;
        int unknown = 0;
        for (SeenObject object : scene.objects()) {
            Cell cell = object.cell();
            if (cell.row() < rows && cell.column() < columns) {
                counts[cell.row()][cell.column()][indexOf(object.kind())]++;
            }
            if (object.kind() == ObjectKind.PLAYER) {
                switch (object.relation()) {
                    case TEAMMATE -> teammates++;
                    case OPPONENT -> opponents++;
                    default -> unknown++;
                }
            }
        }
        String[][] texts = new String[rows][columns];
        int width = 6;
        for (int row = 0; row < rows; row++) {
            for (int column = 0; column < columns; column++) {
                texts[row][column] = cellText(counts[row][column]);
                width = Math.max(width, texts[row][column].length() + 2);
            }
        }
        StringBuilder out = new StringBuilder();
        out.append("Scene cycle ").append(scene.cycle()).append("  ").append(scene.observer().label()).append('\n');
        out.append("Teammates/opponents/unknown players = ")
                .append(teammates).append('/').append(opponents).append('/').append(unknown).append('\n');
        String border = border(columns, width);
        out.append(border);
        for (int row = rows - 1; row >= 0; row--) {
            out.append('|');
            for (int column = 0; column < columns; column++) {
                String text = texts[row][column];
                int left = (width - text.length()) / 2;
                out.append(" ".repeat(left)).append(text).append(" ".repeat(width - text.length() - left)).append('|');
            }
            out.append('\n').append(border);
        }
        if (scene.actions().isEmpty()) {
            out.append("action: none\n");
        }
        for (int i = 0; i < scene.actions().size(); i++) {
            out.append(i == 0 ? "action: " : "also:   ").append(scene.actions().get(i).describe()).append('\n');
        }
        return out.toString();
    }

    private static int indexOf(ObjectKind kind) {
        for (int i = 0; i < ORDER.length; i++) {
            if (ORDER[i] == kind) {
                return i;
            }
        }
        throw new IllegalStateException(kind.toString());
    }

    private static String cellText(int[] counts) {
        StringBuilder text = new StringBuilder();
        for (int i = 0; i < ORDER.length; i++) {
            if (counts[i] == 0) {
                continue;
            }
            if (text.length() > 0) {
                text.append(' ');
            }
            boolean single = ORDER[i] == ObjectKind.BALL || ORDER[i] == ObjectKind.GOAL;
            if (!(single && counts[i] == 1)) {
                text.append(counts[i]);
            }
            text.append(LETTERS[i]);
        }
        return text.toString();
    }

    private static String border(int columns, int width) {
        String segment = "-".repeat(width);
        StringBuilder line = new StringBuilder("+");
        for (int column = 0; column < columns; column++) {
            line.append(segment).append('+');
        }
        return line.append('\n').toString();
    }
}
