package org.scenes.plugins.script;

import groovy.lang.GroovyClassLoader;
import groovy.lang.GroovyCodeSource;
import groovy.lang.Script;
import groovy.transform.CompileStatic;
import groovy.transform.ThreadInterrupt;
import java.io.IOException;
import java.nio.charset.MalformedInputException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.codehaus.groovy.control.CompilationFailedException;
import org.codehaus.groovy.control.CompilerConfiguration;
import org.codehaus.groovy.control.MultipleCompilationErrorsException;
import org.codehaus.groovy.control.customizers.ASTTransformationCustomizer;
import org.codehaus.groovy.control.customizers.ImportCustomizer;
import org.codehaus.groovy.control.messages.ExceptionMessage;
import org.codehaus.groovy.control.messages.Message;
import org.codehaus.groovy.control.messages.SimpleMessage;
import org.codehaus.groovy.control.messages.SyntaxErrorMessage;
import org.codehaus.groovy.syntax.SyntaxException;
import org.scenes.api.PluginException;

/**
 * Compiles a script file into a subclass of a base script class, statically (so type errors
 * come out at compile time and calls run at Java speed), once per file content: the
 * recognizer creates one metric per thread, and each gets its own instance of the one class.
 */
final class ScriptCompiler {
    /** The Grape transform downloads dependencies named by {@code @Grab}; scripts never download. */
    private static final String GRAB_TRANSFORM = "groovy.grape.GrabAnnotationTransformation";

    private static final Pattern RECORD_ACCESS = Pattern.compile(
            "^Access to [\\w.$]+#(\\w+) is forbidden");

    private static final Map<Key, Class<? extends Script>> COMPILED = new ConcurrentHashMap<>();

    private record Key(Path file, String text, Class<? extends Script> base) {
    }

    private ScriptCompiler() {
    }

    /**
     * @param what what the script is for, in messages ("metric", "selector", "sweep")
     * @param argument the path as the user wrote it, used in every message
     * @param base the script base class, which declares what the script must implement
     */
    static <T extends Script> Class<? extends T> compile(String what, String argument, Class<T> base) {
        if (argument.isBlank()) {
            throw new PluginException("the " + what + " script needs a file: script:PATH, e.g. script:examples/scripts/"
                    + (what.equals("selector") ? "vote" : "ball-goal") + ".groovy");
        }
        Path file = Path.of(argument);
        String text = read(what, argument, file);
        Key key = new Key(file.toAbsolutePath().normalize(), text, base);
        Class<? extends Script> compiled = COMPILED.computeIfAbsent(key, k -> compile(what, argument, text, base));
        return compiled.asSubclass(base);
    }

    private static String read(String what, String argument, Path file) {
        if (Files.isDirectory(file)) {
            throw new PluginException("the " + what + " script " + argument + " is a directory, not a .groovy file");
        }
        try {
            return Files.readString(file);
        } catch (NoSuchFileException e) {
            throw new PluginException("the " + what + " script " + argument + " does not exist (looked in "
                    + file.toAbsolutePath().normalize() + ")");
        } catch (MalformedInputException e) {
            throw new PluginException("the " + what + " script " + argument + " is not UTF-8 text");
        } catch (IOException e) {
            throw new PluginException("cannot read the " + what + " script " + argument + ": " + e.getMessage(), e);
        }
    }

    private static Class<? extends Script> compile(String what, String argument, String text, Class<? extends Script> base) {
        CompilerConfiguration configuration = configuration(base);
        // The parent is the plugin's loader: scripts see core, Groovy and this plugin, nothing else.
        try (GroovyClassLoader loader = new GroovyClassLoader(base.getClassLoader(), configuration)) {
            String fileName = Path.of(argument).getFileName().toString();
            GroovyCodeSource source = new GroovyCodeSource(text, fileName, "/groovy/script");
            source.setCachable(false);
            Class<?> compiled = loader.parseClass(source, false);
            if (!base.isAssignableFrom(compiled)) {
                throw new PluginException(argument + ": the " + what + " script declares only classes; write "
                        + (base == SweepScript.class ? "the sweep's statements" : "the " + ScriptShape.of(base).method() + " method")
                        + " at the top level of the file (see docs/scripting.md)");
            }
            return compiled.asSubclass(base);
        } catch (MultipleCompilationErrorsException e) {
            throw new PluginException(describe(what, argument, e), e);
        } catch (CompilationFailedException e) {
            throw new PluginException("the " + what + " script " + argument + " does not compile: " + e.getMessage(), e);
        } catch (IOException e) {
            throw new PluginException("cannot compile the " + what + " script " + argument + ": " + e.getMessage(), e);
        }
    }

    static CompilerConfiguration configuration(Class<? extends Script> base) {
        CompilerConfiguration configuration = new CompilerConfiguration();
        configuration.setScriptBaseClass(base.getName());
        configuration.setSourceEncoding("UTF-8");
        configuration.setDisabledGlobalASTTransformations(Set.of(GRAB_TRANSFORM));
        ImportCustomizer imports = new ImportCustomizer();
        // scripts are plugins: they see the plugin API, never core's internals
        imports.addStarImports("org.scenes.api");
        imports.addImports("java.util.random.RandomGenerator");
        configuration.addCompilationCustomizers(
                imports,
                new ForbiddenCallsCustomizer.NoGrab(),
                new PrimitiveFieldsCustomizer(),
                new ScriptShape.Check(ScriptShape.of(base)),
                new ASTTransformationCustomizer(CompileStatic.class),
                // loops and methods check the interrupt flag, so ScriptWatch can end a call that never returns
                new ASTTransformationCustomizer(ThreadInterrupt.class),
                new ForbiddenCallsCustomizer(),
                new FastEqualityCustomizer());
        return configuration;
    }

    /** One line per error, each {@code file:line:column: message}, under a line naming the script. */
    static String describe(String what, String argument, MultipleCompilationErrorsException failure) {
        // Static type checking reports one mistake again in every enclosing expression of the
        // line; the first report of a line is the precise one.
        Map<Integer, String> byLine = new LinkedHashMap<>();
        List<String> lines = new ArrayList<>();
        for (Object error : failure.getErrorCollector().getErrors()) {
            int line = error instanceof SyntaxErrorMessage syntax ? syntax.getCause().getLine() : 0;
            String text = describe(argument, (Message) error);
            if (line <= 0 ? !lines.contains(text) : byLine.putIfAbsent(line, text) == null) {
                lines.add(text);
            }
        }
        return "the " + what + " script " + argument + " does not compile:\n  " + String.join("\n  ", lines);
    }

    private static String describe(String argument, Message message) {
        if (message instanceof SyntaxErrorMessage syntax) {
            SyntaxException cause = syntax.getCause();
            String location = cause.getLine() > 0
                    ? argument + ":" + cause.getLine() + ":" + Math.max(1, cause.getStartColumn())
                    : argument;
            return location + ": " + hint(oneLine(cause.getOriginalMessage()));
        }
        if (message instanceof ExceptionMessage exception) {
            return argument + ": " + oneLine(String.valueOf(exception.getCause().getMessage()));
        }
        if (message instanceof SimpleMessage simple) {
            return argument + ": " + oneLine(simple.getMessage());
        }
        return argument + ": " + message;
    }

    /** Scene types are Java records: Groovy refuses {@code scene.cycle}, which users write first. */
    private static String hint(String message) {
        Matcher access = RECORD_ACCESS.matcher(message);
        if (access.find()) {
            return message + " (scene values are Java records: read them with " + access.group(1) + "())";
        }
        return message;
    }

    private static String oneLine(String text) {
        return text.strip().replaceAll("\\s*\\R\\s*", " ");
    }
}
