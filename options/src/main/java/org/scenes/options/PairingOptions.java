package org.scenes.options;

import org.scenes.internal.convert.Pairing;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Option;
import picocli.CommandLine.TypeConversionException;

/** {@code --pairing} and {@code --strict}: how a player log's sees and actions become scenes. */
public final class PairingOptions {
    @Option(names = "--strict", description = "Stop at the first malformed line of a log instead of skipping it.")
    private boolean strict;

    @Option(names = "--pairing", paramLabel = "see|cycle|auto", defaultValue = "auto",
            converter = PairingConverter.class,
            description = {"How sees and actions become scenes: see (a scene per see, the classic rule),"
                    + " cycle (a scene per cycle with the latest see and its age, for players that act every cycle),"
                    + " auto (cycle once the server confirms synchronous vision with (ok synch_see); default)."})
    private Pairing pairing;

    public boolean strict() {
        return strict;
    }

    public Pairing pairing() {
        return pairing;
    }

    static final class PairingConverter implements ITypeConverter<Pairing> {
        @Override
        public Pairing convert(String value) {
            Pairing pairing = Pairing.fromKey(value);
            if (pairing == null) {
                throw new TypeConversionException("expected see, cycle or auto, not '" + value + "'");
            }
            return pairing;
        }
    }
}
