package org.scenes.plugins.script;

import org.codehaus.groovy.ast.AnnotationNode;
import org.codehaus.groovy.ast.ClassCodeVisitorSupport;
import org.codehaus.groovy.ast.ClassHelper;
import org.codehaus.groovy.ast.ClassNode;
import org.codehaus.groovy.ast.expr.ConstantExpression;
import org.codehaus.groovy.ast.expr.DeclarationExpression;
import org.codehaus.groovy.ast.expr.EmptyExpression;
import org.codehaus.groovy.ast.expr.VariableExpression;
import org.codehaus.groovy.classgen.GeneratorContext;
import org.codehaus.groovy.control.CompilePhase;
import org.codehaus.groovy.control.SourceUnit;
import org.codehaus.groovy.control.customizers.CompilationCustomizer;

/**
 * Keeps {@code @Field double x} a primitive field. Groovy 4 types a script-level declaration
 * with the wrapper class and {@code @Field} copies that type, so the field becomes a
 * {@code Double}: boxed on every write in the matching loop, and {@code null} (not 0) when it
 * has no initial value, which makes {@code calls++} throw. The declared type is still known
 * as the variable's origin type; this restores it before {@code @Field} makes the field, and
 * gives a primitive field without initial value the Java default (0, false).
 */
final class PrimitiveFieldsCustomizer extends CompilationCustomizer {
    PrimitiveFieldsCustomizer() {
        super(CompilePhase.CONVERSION);
    }

    @Override
    public void call(SourceUnit source, GeneratorContext context, ClassNode classNode) {
        if (!classNode.isScript()) {
            return;
        }
        new ClassCodeVisitorSupport() {
            @Override
            protected SourceUnit getSourceUnit() {
                return source;
            }

            @Override
            public void visitDeclarationExpression(DeclarationExpression declaration) {
                if (!declaration.isMultipleAssignmentDeclaration() && isField(declaration)) {
                    VariableExpression variable = declaration.getVariableExpression();
                    ClassNode type = variable.getOriginType();
                    if (ClassHelper.isPrimitiveType(type)) {
                        variable.setType(type);
                        if (declaration.getRightExpression() instanceof EmptyExpression) {
                            // Groovy's constructor code cannot store "no value" into a primitive field.
                            declaration.setRightExpression(new ConstantExpression(zero(type), true));
                        }
                    }
                }
                super.visitDeclarationExpression(declaration);
            }
        }.visitClass(classNode);
    }

    private static Object zero(ClassNode type) {
        return switch (type.getName()) {
            case "boolean" -> Boolean.FALSE;
            case "char" -> Character.valueOf('\0');
            case "byte" -> Byte.valueOf((byte) 0);
            case "short" -> Short.valueOf((short) 0);
            case "long" -> Long.valueOf(0);
            case "float" -> Float.valueOf(0);
            case "double" -> Double.valueOf(0);
            default -> Integer.valueOf(0);
        };
    }

    private static boolean isField(DeclarationExpression declaration) {
        for (AnnotationNode annotation : declaration.getAnnotations()) {
            String name = annotation.getClassNode().getName();
            if (name.equals("Field") || name.equals("groovy.transform.Field")) {
                return true;
            }
        }
        return false;
    }
}
