package org.scenes.cli;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Map;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.internal.validate.MatchConfigFile;

/**
 * The commands' JSON printer, and the configuration files of {@code scenes tune} and {@code --config}
 * (their format is core's {@link MatchConfigFile}; here a file that cannot be read is a usage error).
 */
final class ConfigFiles {
    static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    private ConfigFiles() {
    }

    static void write(Path file, MatchConfig config, Map<String, Object> extra) throws IOException {
        MatchConfigFile.write(file, config, extra);
    }

    /** Reads a configuration; a key that is unknown or of the wrong type is an error naming the key and the file. */
    static MatchConfig read(Path file) {
        try {
            return MatchConfigFile.read(file);
        } catch (MatchConfigFile.InvalidException e) {
            throw new UsageException(e.getMessage());
        }
    }
}
