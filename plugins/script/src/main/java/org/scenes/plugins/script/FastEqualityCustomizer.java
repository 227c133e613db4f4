package org.scenes.plugins.script;

import org.codehaus.groovy.ast.ClassCodeExpressionTransformer;
import org.codehaus.groovy.ast.ClassHelper;
import org.codehaus.groovy.ast.ClassNode;
import org.codehaus.groovy.ast.expr.ArgumentListExpression;
import org.codehaus.groovy.ast.expr.BinaryExpression;
import org.codehaus.groovy.ast.expr.ClassExpression;
import org.codehaus.groovy.ast.expr.Expression;
import org.codehaus.groovy.ast.expr.MethodCallExpression;
import org.codehaus.groovy.classgen.GeneratorContext;
import org.codehaus.groovy.control.CompilePhase;
import org.codehaus.groovy.control.SourceUnit;
import org.codehaus.groovy.control.customizers.CompilationCustomizer;
import org.codehaus.groovy.syntax.Token;
import org.codehaus.groovy.syntax.Types;
import org.codehaus.groovy.transform.stc.StaticTypesMarker;

/**
 * Compiles {@code ==} and {@code !=} between two enum values ({@code object.kind() == ObjectKind.BALL})
 * or two primitive booleans to a reference comparison, as fast as Java's. Even statically
 * compiled, Groovy sends these through its general equality routine (null, number, string and
 * {@code compareTo} checks), which made a metric that looks objects up by kind and relation
 * about twenty times slower than Java. The result is the same: each enum constant is its only
 * instance, and a primitive boolean is boxed to one of the two canonical {@code Boolean}s. Runs after static type
 * checking, which tells the operands' types, and after static compilation rewrote equality into
 * a call of Groovy's runtime.
 */
final class FastEqualityCustomizer extends CompilationCustomizer {
    private static final String ADAPTER = "org.codehaus.groovy.runtime.ScriptBytecodeAdapter";

    FastEqualityCustomizer() {
        super(CompilePhase.INSTRUCTION_SELECTION);
    }

    @Override
    public void call(SourceUnit source, GeneratorContext context, ClassNode classNode) {
        new ClassCodeExpressionTransformer() {
            @Override
            protected SourceUnit getSourceUnit() {
                return source;
            }

            @Override
            public Expression transform(Expression expression) {
                Expression[] operands = equalityOperands(expression);
                if (operands != null && (isEnum(operands[0]) && isEnum(operands[1])
                        || isBoolean(operands[0]) && isBoolean(operands[1]))) {
                    int identity = isNegated(expression) ? Types.COMPARE_NOT_IDENTICAL : Types.COMPARE_IDENTICAL;
                    BinaryExpression replaced = new BinaryExpression(transform(operands[0]),
                            Token.newSymbol(identity, expression.getLineNumber(), expression.getColumnNumber()),
                            transform(operands[1]));
                    replaced.setSourcePosition(expression);
                    replaced.setNodeMetaData(StaticTypesMarker.INFERRED_TYPE, ClassHelper.boolean_TYPE);
                    return replaced;
                }
                return super.transform(expression);
            }
        }.visitClass(classNode);
    }

    /**
     * The two operands of an equality test, or null: static compilation has by now turned
     * {@code a == b} into {@code ScriptBytecodeAdapter.compareEqual(a, b)}; a plain binary
     * expression is accepted too in case a Groovy version leaves it.
     */
    private static Expression[] equalityOperands(Expression expression) {
        if (expression instanceof BinaryExpression binary) {
            int type = binary.getOperation().getType();
            if (type == Types.COMPARE_EQUAL || type == Types.COMPARE_NOT_EQUAL) {
                return new Expression[] {binary.getLeftExpression(), binary.getRightExpression()};
            }
        } else if (expression instanceof MethodCallExpression call
                && call.getObjectExpression() instanceof ClassExpression owner
                && owner.getType().getName().equals(ADAPTER)
                && (call.getMethodAsString().equals("compareEqual") || call.getMethodAsString().equals("compareNotEqual"))
                && call.getArguments() instanceof ArgumentListExpression arguments
                && arguments.getExpressions().size() == 2) {
            return new Expression[] {arguments.getExpression(0), arguments.getExpression(1)};
        }
        return null;
    }

    private static boolean isNegated(Expression expression) {
        if (expression instanceof BinaryExpression binary) {
            return binary.getOperation().getType() == Types.COMPARE_NOT_EQUAL;
        }
        return ((MethodCallExpression) expression).getMethodAsString().equals("compareNotEqual");
    }

    private static boolean isEnum(Expression expression) {
        ClassNode type = typeOf(expression);
        return type != null && type.isEnum();
    }

    private static boolean isBoolean(Expression expression) {
        ClassNode type = typeOf(expression);
        return type != null && ClassHelper.isPrimitiveBoolean(type);
    }

    private static ClassNode typeOf(Expression expression) {
        ClassNode type = expression.getNodeMetaData(StaticTypesMarker.INFERRED_TYPE);
        return type != null ? type : expression.getType();
    }
}
