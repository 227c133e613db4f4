package org.scenes.script;

import groovy.lang.Script;
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
            for (MethodNode candidate : classNode.getMethods(shape.name)) {
                if (candidate.getParameters().length == shape.parameters) {
                    return;
                }
            }
            String kind = shape.name().toLowerCase(java.util.Locale.ROOT);
            source.addError(new SyntaxException("a " + kind + " script must define the method " + shape.method
                    + " at its top level", 1, 1));
        }
    }
}
