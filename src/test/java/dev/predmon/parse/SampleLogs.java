package dev.predmon.parse;

import java.util.Locale;
import java.util.Random;

/** Generated logs that mix every variant a text log may hold, for the stream-level tests. */
final class SampleLogs {
    private SampleLogs() {
    }

    /**
     * A log of {@code records} current-format records (each preceded by its INFO raw bottle, some followed by
     * another component's WARNING), with CRLF endings on some lines and varied spacing.
     */
    static String mixed(int records, long seed) {
        Random random = new Random(seed);
        StringBuilder log = new StringBuilder();
        for (int i = 0; i < records; i++) {
            String time = String.format(Locale.ROOT, "%.6f", 1606737474.0 + i * 0.25);
            String sep = random.nextBoolean() ? "\t" : " ";
            String eol = random.nextInt(4) == 0 ? "\r\n" : "\n";
            boolean reply = i % 2 == 1;
            log.append(time).append(" INFO \"/GoToGoToClient/kitchen\" \"/GoToComponent\" \"")
                    .append(reply ? "reply" : "command").append("\" \"GoTo\" (getStatus) (kitchen) (1)").append(eol);
            log.append(time).append(sep).append("DEBUG").append(sep).append(reply ? "Reply" : "Command")
                    .append(" intercepted:").append(eol);
            log.append("  From      : /p").append(i).append(eol);
            log.append("  To        : /q").append(eol);
            log.append("  Protocol  : GoTo").append(eol);
            log.append("  Command   : getStatus").append(eol);
            log.append("  Arguments : kitchen").append(eol);
            log.append("  Reply     : ").append(reply ? "1" : "").append(eol);
            if (random.nextInt(3) == 0) {
                log.append(time).append(" WARNING goTo called with destination kitchen").append(eol);
            }
        }
        return log.toString();
    }
}
