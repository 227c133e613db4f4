package org.scenes.testing;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;
import org.junit.jupiter.api.extension.ConditionEvaluationResult;
import org.junit.jupiter.api.extension.ExecutionCondition;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.extension.ExtensionContext;

/**
 * The annotated test class or method reads the shared real recordings ({@link SharedData}) and is
 * skipped with {@link SharedData#absentMessage()} when they are absent. Checked before
 * {@code @BeforeAll}, so a class may load the recordings there.
 */
@Target({ElementType.TYPE, ElementType.METHOD})
@Retention(RetentionPolicy.RUNTIME)
@ExtendWith(RequiresSharedData.Condition.class)
public @interface RequiresSharedData {
    /** Evaluates the annotation; public only because JUnit instantiates it. */
    final class Condition implements ExecutionCondition {
        @Override
        public ConditionEvaluationResult evaluateExecutionCondition(ExtensionContext context) {
            return SharedData.present() ? ConditionEvaluationResult.enabled("the shared recordings are present")
                    : ConditionEvaluationResult.disabled(SharedData.absentMessage());
        }
    }
}
