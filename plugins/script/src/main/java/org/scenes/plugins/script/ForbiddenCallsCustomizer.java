package org.scenes.plugins.script;

import java.util.Set;
import org.codehaus.groovy.ast.ASTNode;
import org.codehaus.groovy.ast.AnnotatedNode;
import org.codehaus.groovy.ast.AnnotationNode;
import org.codehaus.groovy.ast.ClassCodeVisitorSupport;
import org.codehaus.groovy.ast.ClassNode;
import org.codehaus.groovy.ast.ImportNode;
import org.codehaus.groovy.ast.MethodNode;
import org.codehaus.groovy.ast.expr.ClassExpression;
import org.codehaus.groovy.ast.expr.Expression;
import org.codehaus.groovy.ast.expr.MethodCallExpression;
import org.codehaus.groovy.ast.expr.MethodPointerExpression;
import org.codehaus.groovy.ast.expr.StaticMethodCallExpression;
import org.codehaus.groovy.classgen.GeneratorContext;
import org.codehaus.groovy.control.CompilePhase;
import org.codehaus.groovy.control.SourceUnit;
import org.codehaus.groovy.control.customizers.CompilationCustomizer;
import org.codehaus.groovy.syntax.SyntaxException;
import org.codehaus.groovy.transform.stc.StaticTypesMarker;

/**
 * Rejects calls that end the JVM ({@code System.exit}, {@code Runtime.exit}, {@code Runtime.halt})
 * at compile time, so a script copied from a command-line program cannot kill a long
 * validation run or a game by accident. It runs after static type checking and so also sees
 * calls through variables ({@code Runtime rt = Runtime.getRuntime(); rt.halt(1)}). This is a
 * guard against mistakes, not a security boundary: scripts are trusted local code, and
 * reflection or a dynamically compiled block can still reach these methods.
 */
final class ForbiddenCallsCustomizer extends CompilationCustomizer {
    private static final Set<String> SYSTEM = Set.of("exit");
    private static final Set<String> RUNTIME = Set.of("exit", "halt");

    ForbiddenCallsCustomizer() {
        super(CompilePhase.INSTRUCTION_SELECTION);
    }

    @Override
    public void call(SourceUnit source, GeneratorContext context, ClassNode classNode) {
        new Visitor(source).visitClass(classNode);
    }

    static boolean forbidden(String owner, String method) {
        return ("java.lang.System".equals(owner) && SYSTEM.contains(method))
                || ("java.lang.Runtime".equals(owner) && RUNTIME.contains(method));
    }

    private static final class Visitor extends ClassCodeVisitorSupport {
        private final SourceUnit source;

        Visitor(SourceUnit source) {
            this.source = source;
        }

        @Override
        protected SourceUnit getSourceUnit() {
            return source;
        }

        @Override
        public void visitMethodCallExpression(MethodCallExpression call) {
            MethodNode target = call.getNodeMetaData(StaticTypesMarker.DIRECT_METHOD_CALL_TARGET);
            String owner = target != null ? target.getDeclaringClass().getName() : staticOwner(call.getObjectExpression());
            String name = target != null ? target.getName() : call.getMethodAsString();
            check(owner, name, call);
            super.visitMethodCallExpression(call);
        }

        @Override
        public void visitStaticMethodCallExpression(StaticMethodCallExpression call) {
            check(call.getOwnerType().getName(), call.getMethod(), call);
            super.visitStaticMethodCallExpression(call);
        }

        @Override
        public void visitMethodPointerExpression(MethodPointerExpression pointer) {
            check(staticOwner(pointer.getExpression()), pointer.getMethodName().getText(), pointer);
            super.visitMethodPointerExpression(pointer);
        }

        private static String staticOwner(Expression receiver) {
            return receiver instanceof ClassExpression type ? type.getType().getName() : null;
        }

        private void check(String owner, String method, ASTNode where) {
            if (owner != null && method != null && forbidden(owner, method)) {
                String simple = owner.substring(owner.lastIndexOf('.') + 1);
                source.addError(new SyntaxException(simple + "." + method + " would stop the whole program; a script "
                        + "reports a problem by throwing an exception instead", where.getLineNumber(),
                        where.getColumnNumber(), where.getLastLineNumber(), where.getLastColumnNumber()));
            }
        }
    }

    /** Rejects {@code @Grab} and its relatives: a script must not download code. */
    static final class NoGrab extends CompilationCustomizer {
        private static final Set<String> GRAPE = Set.of("Grab", "Grapes", "GrabResolver", "GrabConfig", "GrabExclude");

        NoGrab() {
            super(CompilePhase.CONVERSION);
        }

        @Override
        public void call(SourceUnit source, GeneratorContext context, ClassNode classNode) {
            for (ImportNode node : source.getAST().getImports()) {
                check(source, node);
            }
            for (ImportNode node : source.getAST().getStarImports()) {
                check(source, node);
            }
            for (ImportNode node : source.getAST().getStaticImports().values()) {
                check(source, node);
            }
            for (ImportNode node : source.getAST().getStaticStarImports().values()) {
                check(source, node);
            }
            new ClassCodeVisitorSupport() {
                @Override
                protected SourceUnit getSourceUnit() {
                    return source;
                }

                @Override
                public void visitAnnotations(AnnotatedNode node) {
                    check(source, node);
                    super.visitAnnotations(node);
                }
            }.visitClass(classNode);
        }

        private static void check(SourceUnit source, AnnotatedNode node) {
            for (AnnotationNode annotation : node.getAnnotations()) {
                String name = annotation.getClassNode().getName();
                String simple = name.substring(name.lastIndexOf('.') + 1);
                if (GRAPE.contains(simple)) {
                    source.addError(new SyntaxException("@" + simple + " is not allowed: scripts do not download "
                            + "libraries", annotation.getLineNumber(),
                            annotation.getColumnNumber(), annotation.getLastLineNumber(), annotation.getLastColumnNumber()));
                }
            }
        }
    }
}
