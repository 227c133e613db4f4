package org.scenes.internal.match;

import java.util.ArrayList;
import java.util.List;
import java.util.NavigableMap;
import java.util.SortedMap;
import java.util.TreeMap;
import java.util.function.Supplier;
import java.util.function.UnaryOperator;
import org.scenes.api.EncodedMetric;
import org.scenes.api.Neighbour;
import org.scenes.api.PackedMetric;
import org.scenes.api.PluginException;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.api.SceneTransform;
import org.scenes.api.TopK;

/**
 * k-nearest-neighbour search of a query scene against a knowledge base: the one implementation
 * behind validation, the live agent and benchmarks. It keeps the k best in a bounded max-heap;
 * equal distances are ordered by knowledge-base index, so results never depend on timing or
 * threads. Metrics with an {@link EncodedMetric} fast path have the knowledge base encoded once
 * here and are asked with the current k-th best distance as bound, so they can stop early;
 * metrics with a {@link PackedMetric} form have it built once here and scan it themselves;
 * other metrics compare whole scenes, decoded from the knowledge base once here (at the memory
 * cost of scene objects).
 * Safe to use from several threads: each thread gets its own metric instance.
 */
public final class Recognizer {
    private final KnowledgeBase knowledge;
    private final int k;
    private final ThreadLocal<SceneMetric> metrics;
    private final Object[] encoded;
    private final PackedMetric.PackedScenes packed;
    /**
     * Knowledge bases of at most this many scenes are kept decoded (a few megabytes), so a decision
     * does not decode its neighbours: on a condensed knowledge base that decoding would cost more
     * than the search itself (ball-goal on 137 scenes).
     */
    static final int KEEP_DECODED = 4096;
    /** The index of the entries that bound a search from the start; no stored scene has it. */
    private static final int PLACEHOLDER = Integer.MAX_VALUE;

    /** decoded scenes for metrics with neither fast path, which compare whole scenes, and for small knowledge bases */
    private final List<Scene> decoded;
    /**
     * Slots of a direct-mapped cache of recently decoded neighbours (a power of two), for knowledge
     * bases too large to keep decoded: a player's consecutive decisions share many neighbours (its
     * view changes little from one cycle to the next), and decoding a HELIOS scene from the compact
     * store costs some 3 us, most of a k = 10 decision's. A decoded HELIOS base scene takes about
     * 6 kB, so 3 MB per recognizer at most, whatever the knowledge base's size: 512 slots took the
     * p50 of a k = 10 decision in play order from 30.5 to 27.2 us (FieldIndexBench.decideAsAgent,
     * queries=played), as 2,048 did (26.4 us) at a quarter of the memory.
     */
    static final int RECENT_SLOTS = 512;
    /**
     * The cache, null when {@link #decoded} holds every scene. Shared by the threads without locks:
     * an entry is immutable with final fields, so it is safely published; two threads writing a slot
     * at once only cost a later decode again.
     */
    private final DecodedScene[] recent;
    /** The knowledge base split by see age, or null when all its scenes have one age. */
    private final NavigableMap<Integer, AgePartition> byAge;
    /** The second orientation queries are matched in (see {@link SceneTransform#queryImage}), or null. */
    private final UnaryOperator<Scene> queryImage;

    public Recognizer(KnowledgeBase knowledge, Supplier<SceneMetric> metricFactory, int k) {
        this(knowledge, metricFactory, k, null);
    }

    /**
     * @param queryImage null, or an involution (the mirror image): each query is then matched as it
     *                   is and as its image, and a stored scene found for the image is returned as
     *                   its own image, whose actions suit the query; as if the knowledge base held
     *                   the images of its scenes too, without storing them
     */
    public Recognizer(KnowledgeBase knowledge, Supplier<SceneMetric> metricFactory, int k, UnaryOperator<Scene> queryImage) {
        this(knowledge, metricFactory, k, true, queryImage);
    }

    private Recognizer(KnowledgeBase knowledge, Supplier<SceneMetric> metricFactory, int k, boolean splitByAge,
                       UnaryOperator<Scene> queryImage) {
        this.queryImage = queryImage;
        if (k < 1) {
            throw new IllegalArgumentException("k must be at least 1, not " + k);
        }
        if (knowledge.size() == 0) {
            throw new IllegalArgumentException("the knowledge base holds no scenes");
        }
        this.knowledge = knowledge;
        this.k = k;
        this.metrics = ThreadLocal.withInitial(metricFactory);
        byAge = splitByAge ? partitionByAge(knowledge, metricFactory, k) : null;
        if (byAge != null) {
            packed = null;
            encoded = null;
            decoded = null;
            recent = null;
            return;
        }
        SceneMetric first = metricFactory.get();
        packed = first instanceof PackedMetric packable ? packable.pack(knowledge.scenes()) : null;
        if (packed == null && first instanceof EncodedMetric<?> fast) {
            encoded = new Object[knowledge.size()];
            for (int i = 0; i < encoded.length; i++) {
                encoded[i] = fast.encode(knowledge.scene(i));
            }
        } else {
            encoded = null;
        }
        decoded = packed == null && encoded == null || knowledge.size() <= KEEP_DECODED
                ? List.copyOf(knowledge.scenes()) : null;
        recent = decoded == null ? new DecodedScene[RECENT_SLOTS] : null;
    }

    /** A stored scene decoded, with its index in the knowledge base. */
    private record DecodedScene(int index, Scene scene) {
    }

    /** The stored scene {@code index}: kept decoded, recently decoded, or decoded now and remembered. */
    private Scene scene(int index) {
        if (decoded != null) {
            return decoded.get(index);
        }
        int slot = index & (RECENT_SLOTS - 1);
        DecodedScene entry = recent[slot];
        if (entry != null && entry.index() == index) {
            return entry.scene();
        }
        Scene scene = knowledge.scene(index);
        recent[slot] = new DecodedScene(index, scene);
        return scene;
    }

    /** The scenes of one see age, searched on their own, and where they are in the whole knowledge base. */
    private record AgePartition(Recognizer recognizer, int[] indices) {
    }

    /**
     * A player acting every cycle on a see every other cycle shows the same view in two cycles and
     * acts differently in each (it predicts the cycle in between): scenes of different see ages are
     * different situations, so each age is searched apart. Null when every scene has one age.
     */
    private static NavigableMap<Integer, AgePartition> partitionByAge(KnowledgeBase knowledge,
                                                                            Supplier<SceneMetric> metricFactory, int k) {
        SortedMap<Integer, KnowledgeBase.AgePart> parts = knowledge.byAge(); // split once per knowledge base
        if (parts.isEmpty()) {
            return null;
        }
        TreeMap<Integer, AgePartition> partitions = new TreeMap<>();
        parts.forEach((age, part) -> partitions.put(age, new AgePartition(new Recognizer(part.knowledge(),
                metricFactory, k, false, null), part.indices())));
        return partitions;
    }

    public KnowledgeBase knowledge() {
        return knowledge;
    }

    /**
     * Whether the stored scenes have several see ages (a player that acts every cycle on a see
     * every other cycle), so queries are matched against scenes of their own age only.
     */
    public boolean splitsBySeeAge() {
        return byAge != null;
    }

    public int k() {
        return k;
    }

    public SceneMetric metric() {
        return metrics.get();
    }

    /**
     * The min(k, size) stored scenes nearest to the query, nearest first, ties by index. With a
     * query image, the k nearest of the query's and its image's neighbours (those of the image
     * returned as images, with their stored index); on equal distance the query's own come first.
     */
    public List<Neighbour> nearest(Scene query) {
        return nearest(query, k);
    }

    /**
     * The same for {@code count} neighbours instead of k: a player whose k nearest hold nothing it
     * can carry out looks further.
     */
    public List<Neighbour> nearest(Scene query, int count) {
        if (count < 1) {
            throw new IllegalArgumentException("count must be at least 1, not " + count);
        }
        List<Neighbour> direct = nearestAsIs(query, Double.POSITIVE_INFINITY, count);
        if (queryImage == null) {
            return direct;
        }
        // only image neighbours nearer than the query's own k-th can enter, so the second search starts bounded by it
        double bound = direct.size() == Math.min(count, knowledge.size()) ? direct.get(direct.size() - 1).distance()
                : Double.POSITIVE_INFINITY;
        List<Neighbour> mirrored = nearestAsIs(queryImage.apply(query), bound, count);
        List<Neighbour> merged = new ArrayList<>(direct.size());
        int d = 0;
        int m = 0;
        while (merged.size() < direct.size()) {
            if (m < mirrored.size() && (d == direct.size()
                    || Double.compare(mirrored.get(m).distance(), direct.get(d).distance()) < 0)) {
                Neighbour found = mirrored.get(m++);
                merged.add(new Neighbour(queryImage.apply(found.scene()), found.index(), found.distance()));
            } else {
                merged.add(direct.get(d++));
            }
        }
        return merged;
    }

    /** The {@code count} nearest of the query as it is; with a finite {@code bound}, only those below or at it. */
    private List<Neighbour> nearestAsIs(Scene query, double bound, int count) {
        if (byAge != null) {
            return nearestOfAge(query, bound, count);
        }
        TopK top = new TopK(Math.min(count, knowledge.size()));
        if (bound < Double.POSITIVE_INFINITY) { // false for NaN
            for (int i = 0; i < top.capacity(); i++) {
                top.offer(bound, PLACEHOLDER); // any scene at the bound has a lower index and still enters
            }
        }
        SceneMetric metric = metrics.get();
        if (packed != null) {
            packed.scan(query, top);
        } else if (encoded != null) {
            @SuppressWarnings("unchecked")
            EncodedMetric<Object> fast = (EncodedMetric<Object>) metric;
            Object q = fast.encode(query);
            for (int i = 0; i < encoded.length; i++) {
                top.offer(checked(metric, fast.distance(q, encoded[i], top.bound()), query, i), i);
            }
        } else {
            for (int i = 0; i < decoded.size(); i++) {
                top.offer(checked(metric, metric.distance(query, decoded.get(i)), query, i), i);
            }
        }
        // placeholders hold the bound's slots until scenes below it arrive: they are no neighbours
        List<Neighbour> result = top.neighbours(i -> i == PLACEHOLDER ? null : scene(i));
        result.removeIf(found -> found.index() == PLACEHOLDER);
        return result;
    }

    /** A distance of a plugin or script: NaN or below 0 would rank scenes by nonsense, so it fails, naming the metric. */
    private double checked(SceneMetric metric, double distance, Scene query, int stored) {
        if (distance >= 0) {
            return distance;
        }
        String name = metric.toString();
        if (name.startsWith(metric.getClass().getName() + "@")) {
            name = metric.getClass().getSimpleName();
        }
        throw new PluginException("metric " + name + " returned " + distance + " comparing the query scene of cycle "
                + query.cycle() + " with the stored scene of cycle " + knowledge.scene(stored).cycle()
                + ": a distance is 0 or more");
    }

    /** Searches the partition of the query's see age, or of the nearest age stored (the lower on a tie). */
    private List<Neighbour> nearestOfAge(Scene query, double bound, int count) {
        int age = query.seeAge();
        Integer below = byAge.floorKey(age);
        Integer above = byAge.ceilingKey(age);
        int chosen = below == null ? above : above == null || age - below <= above - age ? below : above;
        AgePartition partition = byAge.get(chosen);
        List<Neighbour> found = partition.recognizer().nearestAsIs(query, bound, count);
        List<Neighbour> result = new ArrayList<>(found.size());
        for (Neighbour neighbour : found) {
            result.add(new Neighbour(neighbour.scene(), partition.indices()[neighbour.index()], neighbour.distance()));
        }
        return result;
    }
}
