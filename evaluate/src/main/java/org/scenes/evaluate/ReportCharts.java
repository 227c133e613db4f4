package org.scenes.evaluate;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Rectangle;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Rectangle2D;
import java.text.DecimalFormat;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.annotations.XYLineAnnotation;
import org.jfree.chart.annotations.XYShapeAnnotation;
import org.jfree.chart.axis.CategoryAxis;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.labels.StandardCategoryItemLabelGenerator;
import org.jfree.chart.plot.CategoryPlot;
import org.jfree.chart.plot.ValueMarker;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.LookupPaintScale;
import org.jfree.chart.renderer.category.StandardBarPainter;
import org.jfree.chart.renderer.category.StatisticalBarRenderer;
import org.jfree.chart.renderer.xy.XYBlockRenderer;
import org.jfree.chart.renderer.xy.XYLineAndShapeRenderer;
import org.jfree.chart.ui.RectangleAnchor;
import org.jfree.data.statistics.DefaultStatisticalCategoryDataset;
import org.jfree.data.xy.DefaultXYZDataset;
import org.jfree.data.xy.XYSeries;
import org.jfree.data.xy.XYSeriesCollection;
import org.jfree.svg.SVGGraphics2D;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.PlayerState;

/** The report's figures as JFreeChart charts, drawn to inline SVG. */
final class ReportCharts {
    static final Color TEACHER = new Color(0x33, 0x66, 0x99);
    static final Color IMITATOR = new Color(0xcc, 0x66, 0x33);
    private static final double HALF_X = 52.5;
    private static final double HALF_Y = 34;
    private static final double HEAT_CELL = 3;
    private static final double PLAYER_CELL = 5;
    /** Frames per point of a drawn path. */
    static final int PATH_STEP = 3;
    private static int charts;

    private ReportCharts() {
    }

    /** The chart as an SVG element; each gets its own id prefix, as several share one page. */
    static synchronized String svg(JFreeChart chart, int width, int height) {
        System.setProperty("java.awt.headless", "true");
        SVGGraphics2D graphics = new SVGGraphics2D(width, height);
        graphics.setDefsKeyPrefix("chart" + (++charts) + "-");
        // a tenth of a pixel is finer than any screen shows; the default 6 decimals triple the page
        graphics.setGeomDoubleConverter(ReportCharts::tenths);
        chart.draw(graphics, new Rectangle(width, height));
        return graphics.getSVGElement();
    }

    static String tenths(double value) {
        long tenths = Math.round(value * 10);
        return tenths % 10 == 0 ? Long.toString(tenths / 10) : Double.toString(tenths / 10.0);
    }

    /** A row of bars: each category a figure, teacher and imitator side by side with their spread over seeds. */
    static JFreeChart bars(String title, String unit, List<String> labels, List<Spread> teacher, List<Spread> imitator,
                           double factor, String format) {
        DefaultStatisticalCategoryDataset data = new DefaultStatisticalCategoryDataset();
        double top = 0;
        for (int i = 0; i < labels.size(); i++) {
            Spread t = teacher.get(i);
            Spread m = imitator.get(i);
            if (!Double.isNaN(t.mean())) {
                data.add(factor * t.mean(), factor * t.sd(), "teacher", labels.get(i));
                top = Math.max(top, factor * (t.mean() + t.sd()));
            } else {
                data.add((Number) null, null, "teacher", labels.get(i));
            }
            if (!Double.isNaN(m.mean())) {
                data.add(factor * m.mean(), factor * m.sd(), "imitator", labels.get(i));
                top = Math.max(top, factor * (m.mean() + m.sd()));
            } else {
                data.add((Number) null, null, "imitator", labels.get(i));
            }
        }
        CategoryAxis categories = new CategoryAxis(null);
        categories.setMaximumCategoryLabelLines(2);
        categories.setTickLabelFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        NumberAxis values = new NumberAxis(unit);
        values.setRange(0, top <= 0 ? 1 : top * 1.18);
        StatisticalBarRenderer renderer = new StatisticalBarRenderer();
        renderer.setBarPainter(new StandardBarPainter());
        renderer.setShadowVisible(false);
        renderer.setSeriesPaint(0, TEACHER);
        renderer.setSeriesPaint(1, IMITATOR);
        renderer.setErrorIndicatorPaint(Color.DARK_GRAY);
        renderer.setItemMargin(0.05);
        renderer.setDefaultItemLabelGenerator(new StandardCategoryItemLabelGenerator("{2}", new DecimalFormat(format)));
        renderer.setDefaultItemLabelsVisible(true);
        renderer.setDefaultItemLabelFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        CategoryPlot plot = new CategoryPlot(data, categories, values, renderer);
        plot.setBackgroundPaint(Color.WHITE);
        plot.setRangeGridlinePaint(Color.LIGHT_GRAY);
        JFreeChart chart = new JFreeChart(title, new Font(Font.SANS_SERIF, Font.BOLD, 14), plot, true);
        chart.setBackgroundPaint(Color.WHITE);
        return chart;
    }

    /** The Turing figure: one bar per fold-averaged accuracy, with chance (50%) and the target (60%) marked. */
    static JFreeChart turing(TuringTest.Outcome outcome) {
        DefaultStatisticalCategoryDataset data = new DefaultStatisticalCategoryDataset();
        data.add(100 * outcome.accuracy(), 100 * outcome.spread(), "held-out balanced accuracy", "teacher vs imitator");
        NumberAxis values = new NumberAxis("%");
        values.setRange(0, 100);
        StatisticalBarRenderer renderer = new StatisticalBarRenderer();
        renderer.setBarPainter(new StandardBarPainter());
        renderer.setShadowVisible(false);
        renderer.setSeriesPaint(0, new Color(0x66, 0x66, 0x99));
        renderer.setMaximumBarWidth(0.25);
        renderer.setDefaultItemLabelGenerator(new StandardCategoryItemLabelGenerator("{2}", new DecimalFormat("0.0")));
        renderer.setDefaultItemLabelsVisible(true);
        CategoryPlot plot = new CategoryPlot(data, new CategoryAxis(null), values, renderer);
        plot.setBackgroundPaint(Color.WHITE);
        plot.setRangeGridlinePaint(Color.LIGHT_GRAY);
        ValueMarker chance = new ValueMarker(50, Color.GRAY, new BasicStroke(1.5f));
        chance.setLabel("50% = indistinguishable");
        chance.setLabelAnchor(RectangleAnchor.TOP_RIGHT);
        chance.setLabelTextAnchor(org.jfree.chart.ui.TextAnchor.BOTTOM_RIGHT);
        plot.addRangeMarker(chance);
        ValueMarker target = new ValueMarker(60, new Color(0x22, 0x88, 0x22), new BasicStroke(1.5f,
                BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10, new float[] {6, 4}, 0));
        target.setLabel("target <= 60%");
        target.setLabelAnchor(RectangleAnchor.TOP_LEFT);
        target.setLabelTextAnchor(org.jfree.chart.ui.TextAnchor.BOTTOM_LEFT);
        plot.addRangeMarker(target);
        JFreeChart chart = new JFreeChart("Can a classifier tell them apart?", new Font(Font.SANS_SERIF, Font.BOLD, 14),
                plot, false);
        chart.setBackgroundPaint(Color.WHITE);
        return chart;
    }

    /**
     * Each left player's path over the first {@code cycles} frames of a game, on the pitch, a
     * point every {@link #PATH_STEP} frames (a player runs at most about 1 m a cycle).
     */
    static JFreeChart trajectories(String title, List<GameFrame> frames, int cycles) {
        return trajectories(title, frames, cycles, Side.LEFT);
    }

    /** The paths of {@code side}'s players, as they are on the pitch. */
    static JFreeChart trajectories(String title, List<GameFrame> frames, int cycles, Side side) {
        XYSeriesCollection data = new XYSeriesCollection();
        Map<Integer, XYSeries> byPlayer = new TreeMap<>();
        int count = 0;
        for (GameFrame frame : frames) {
            if (count++ > cycles) {
                break;
            }
            if ((count - 1) % PATH_STEP != 0) {
                continue;
            }
            for (PlayerState p : frame.players()) {
                if (p.side() == side) {
                    byPlayer.computeIfAbsent(p.unum(), u -> new XYSeries("player " + u, false, true)).add(p.x(), p.y());
                }
            }
        }
        byPlayer.values().forEach(data::addSeries);
        XYLineAndShapeRenderer renderer = new XYLineAndShapeRenderer(true, false);
        // one SVG path per player rather than an element per segment
        renderer.setDrawSeriesLineAsPath(true);
        for (int i = 0; i < byPlayer.size(); i++) {
            renderer.setSeriesStroke(i, new BasicStroke(1.2f));
        }
        XYPlot plot = pitchPlot(data, renderer);
        JFreeChart chart = new JFreeChart(title, new Font(Font.SANS_SERIF, Font.BOLD, 13), plot, true);
        chart.setBackgroundPaint(Color.WHITE);
        return chart;
    }

    /**
     * Where the ball was during play on, over all games: the share of frames in each 3 m cell, in
     * the frame of the games' team (attacking towards x+: a right team's games are turned round).
     */
    static JFreeChart heatMap(String title, List<PlayedGame> games) {
        return heatMap(title, games, HEAT_CELL, true, (game, frame, cells) -> {
            double sign = game.side() == Side.LEFT ? 1 : -1;
            cells.add(sign * frame.ball().x(), sign * frame.ball().y());
        });
    }

    /** Where the games' team's player {@code unum} was during play on, in its team's frame, per 5 m cell. */
    static JFreeChart playerHeatMap(String title, List<PlayedGame> games, int unum) {
        return heatMap(title, games, PLAYER_CELL, false, (game, frame, cells) -> {
            double sign = game.side() == Side.LEFT ? 1 : -1;
            for (PlayerState p : frame.players()) {
                if (p.side() == game.side() && p.unum() == unum) {
                    cells.add(sign * p.x(), sign * p.y());
                }
            }
        });
    }

    /** Cells of a heat map. */
    private static final class Cells {
        final double cell;
        final double[][] counts;
        long total;

        Cells(double cell) {
            this.cell = cell;
            counts = new double[(int) Math.ceil(2 * (HALF_X + 5) / cell)][(int) Math.ceil(2 * (HALF_Y + 5) / cell)];
        }

        void add(double x, double y) {
            counts[clamp((int) ((x + HALF_X + 5) / cell), counts.length)]
                    [clamp((int) ((y + HALF_Y + 5) / cell), counts[0].length)]++;
            total++;
        }
    }

    /** What a play-on frame of a game adds to a heat map. */
    private interface Positions {
        void add(PlayedGame game, GameFrame frame, Cells cells);
    }

    private static JFreeChart heatMap(String title, List<PlayedGame> games, double cell, boolean axes,
                                      Positions positions) {
        Cells cells = new Cells(cell);
        for (PlayedGame game : games) {
            for (GameFrame frame : game.frames()) {
                if (frame.playMode().equals("play_on")) {
                    positions.add(game, frame, cells);
                }
            }
        }
        double[][] counts = cells.counts;
        long total = cells.total;
        int columns = counts.length;
        int rows = counts[0].length;
        // only the cells the ball visited: the empty ones are the plot's white background
        int visited = 0;
        for (double[] column : counts) {
            for (double count : column) {
                visited += count > 0 ? 1 : 0;
            }
        }
        double[] xs = new double[visited];
        double[] ys = new double[visited];
        double[] zs = new double[visited];
        double max = 0;
        int i = 0;
        for (int c = 0; c < columns; c++) {
            for (int r = 0; r < rows; r++) {
                if (counts[c][r] == 0) {
                    continue;
                }
                xs[i] = -HALF_X - 5 + (c + 0.5) * cell;
                ys[i] = -HALF_Y - 5 + (r + 0.5) * cell;
                zs[i] = 100 * counts[c][r] / total;
                max = Math.max(max, zs[i]);
                i++;
            }
        }
        DefaultXYZDataset data = new DefaultXYZDataset();
        data.addSeries("ball", new double[][] {xs, ys, zs});
        XYBlockRenderer renderer = new XYBlockRenderer();
        renderer.setBlockWidth(cell);
        renderer.setBlockHeight(cell);
        LookupPaintScale scale = new LookupPaintScale(0, Math.max(max, 1e-9) * 1.0001, Color.WHITE);
        int steps = 8;
        for (int s = 0; s < steps; s++) {
            // the lowest step already tinted: a cell the ball visited at all is not white
            float f = (float) (s + 1) / steps;
            scale.add(s == 0 ? 1e-12 : max * s / steps, new Color(1f, 1f - 0.8f * f, 1f - 0.95f * f));
        }
        renderer.setPaintScale(scale);
        XYPlot plot = pitchPlot(data, renderer);
        plot.setBackgroundPaint(Color.WHITE);
        if (!axes) {
            plot.getDomainAxis().setVisible(false);
            plot.getRangeAxis().setVisible(false);
        }
        JFreeChart chart = new JFreeChart(title, new Font(Font.SANS_SERIF, Font.BOLD, axes ? 13 : 11), plot, false);
        chart.setBackgroundPaint(Color.WHITE);
        return chart;
    }

    private static int clamp(int i, int n) {
        return Math.max(0, Math.min(n - 1, i));
    }

    /** A plot in pitch coordinates (y down, as the server's) with the lines drawn over the data. */
    private static XYPlot pitchPlot(org.jfree.data.xy.XYDataset data, org.jfree.chart.renderer.xy.XYItemRenderer renderer) {
        NumberAxis x = new NumberAxis("x (m)");
        x.setRange(-HALF_X - 5, HALF_X + 5);
        NumberAxis y = new NumberAxis("y (m)");
        y.setRange(-HALF_Y - 5, HALF_Y + 5);
        y.setInverted(true);
        XYPlot plot = new XYPlot(data, x, y, renderer);
        plot.setBackgroundPaint(new Color(0xee, 0xf5, 0xee));
        plot.setDomainGridlinesVisible(false);
        plot.setRangeGridlinesVisible(false);
        BasicStroke line = new BasicStroke(1f);
        Color white = new Color(0x55, 0x55, 0x55);
        plot.addAnnotation(new XYShapeAnnotation(new Rectangle2D.Double(-HALF_X, -HALF_Y, 2 * HALF_X, 2 * HALF_Y),
                line, white));
        plot.addAnnotation(new XYLineAnnotation(0, -HALF_Y, 0, HALF_Y, line, white));
        plot.addAnnotation(new XYShapeAnnotation(new Ellipse2D.Double(-9.15, -9.15, 18.3, 18.3), line, white));
        for (int side : new int[] {-1, 1}) {
            double goalLine = side * HALF_X;
            plot.addAnnotation(new XYShapeAnnotation(new Rectangle2D.Double(Math.min(goalLine, goalLine - side * 16.5),
                    -20.16, 16.5, 40.32), line, white));
            plot.addAnnotation(new XYShapeAnnotation(new Rectangle2D.Double(Math.min(goalLine, goalLine + side * 2),
                    -7.01, 2, 14.02), new BasicStroke(2f), Color.BLACK));
        }
        return plot;
    }
}
