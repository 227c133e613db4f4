package org.scenes.plugins.script;

import groovy.lang.Script;
import java.util.Locale;
import org.codehaus.groovy.ast.ClassNode;
import org.codehaus.groovy.ast.MethodNode;
import org.codehaus.groovy.classgen.GeneratorContext;
import org.codehaus.groovy.control.CompilePhase;
import org.codehaus.groovy.control.SourceUnit;
import org.codehaus.groovy.control.customizers.CompilationCustomizer;
import org.codehaus.groovy.syntax.SyntaxException;

/** What each kind of script must define at its top level. */
enum ScriptShape {
    METRIC(MetricScript.class, "distance", 2, "double distance(Scene query, Scene stored)"),
    SELECTOR(SelectorScript.class, "select", 2, "Action select(List<Neighbour> nearest, RandomGenerator random)"),
    /** A sweep is its statements; it defines no method. */
    SWEEP(SweepScript.class, null, 0, "");

    private final Class<? extends Script> base;
    private final String name;
    private final int parameters;
    private final String method;

    ScriptShape(Class<? extends Script> base, String name, int parameters, String method) {
        this.base = base;
        this.name = name;
        this.parameters = parameters;
        this.method = method;
    }

    /** The method's signature as users write it. */
    String method() {
        return method;
    }

    static ScriptShape of(Class<? extends Script> base) {
        for (ScriptShape shape : values()) {
            if (shape.base == base) {
                return shape;
            }
        }
        throw new IllegalArgumentException("no script shape for " + base.getName());
    }

    private static boolean defines(ClassNode classNode, String name, int parameters) {
        for (MethodNode candidate : classNode.getMethods(name)) {
            // getMethods also lists the base class' methods, which do not count
            if (candidate.getDeclaringClass().equals(classNode) && candidate.getParameters().length == parameters) {
                return true;
            }
        }
        return false;
    }

    /**
     * Fails early, with the signature to write, when the script lacks its method: Groovy's own
     * message ("Can't have an abstract method in a non-abstract class") does not say what to do.
     */
    static final class Check extends CompilationCustomizer {
        private final ScriptShape shape;

        Check(ScriptShape shape) {
            super(CompilePhase.SEMANTIC_ANALYSIS);
            this.shape = shape;
        }

        @Override
        public void call(SourceUnit source, GeneratorContext context, ClassNode classNode) {
            if (!classNode.isScript() || shape.name == null) {
                return;
            }
            if (defines(classNode, shape.name, shape.parameters)) {
                return;
            }
            if (shape == METRIC) {
                // the fast form: encode once, compare arrays
                boolean encode = defines(classNode, "encode", 1);
                boolean arrays = defines(classNode, "distance", 3);
                if (encode && arrays) {
                    return;
                }
                if (encode || arrays) {
                    source.addError(new SyntaxException("a metric script with " + (encode ? "encode" : "a 3-argument distance")
                            + " must also define " + (encode ? "double distance(double[] query, double[] stored, double bound)"
                            : "double[] encode(Scene scene)") + " at its top level", 1, 1));
                    return;
                }
            }
            String kind = shape.name().toLowerCase(Locale.ROOT);
            source.addError(new SyntaxException("a " + kind + " script must define the method " + shape.method
                    + (shape == METRIC ? ", or double[] encode(Scene scene) with double distance(double[] query, "
                    + "double[] stored, double bound)," : "") + " at its top level", 1, 1));
        }
    }
}
