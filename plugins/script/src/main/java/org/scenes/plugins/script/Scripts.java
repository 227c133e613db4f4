package org.scenes.plugins.script;

import groovy.lang.Binding;
import groovy.lang.Script;
import java.lang.reflect.InvocationTargetException;
import java.nio.file.Path;
import org.scenes.api.PluginException;

/** Creating and setting up instances of compiled scripts. */
final class Scripts {
    private Scripts() {
    }

    /** A fresh instance (one per metric or selector, so instances are never shared between threads). */
    static <T extends Script> T instantiate(String what, String path, Class<T> base) {
        Class<? extends T> type = ScriptCompiler.compile(what, path, base);
        try {
            T script = type.getDeclaredConstructor().newInstance();
            script.setBinding(new Binding());
            return script;
        } catch (InvocationTargetException e) {
            throw ScriptFailure.of(path, fileName(path), "creating the " + what, e.getCause());
        } catch (ReflectiveOperationException e) {
            throw new PluginException("cannot create the " + what + " script " + path + ": " + e, e);
        }
    }

    /** Runs the statements outside methods once, before the first call. */
    static void setUp(String what, String path, Script script) {
        try {
            script.run();
        } catch (RuntimeException | StackOverflowError | AssertionError e) {
            throw ScriptFailure.of(path, fileName(path), "setting up the " + what, e);
        }
    }

    static String fileName(String path) {
        return Path.of(path).getFileName().toString();
    }
}
