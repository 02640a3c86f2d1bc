package dev.predmon.cli;

import dev.predmon.BadInputException;

import java.io.BufferedOutputStream;
import java.io.BufferedWriter;
import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.PrintWriter;
import java.nio.charset.Charset;
import java.nio.charset.IllegalCharsetNameException;
import java.nio.charset.UnsupportedCharsetException;

/**
 * Standard output that notices when a write fails. {@code System.out} and picocli's writer over it keep a failed
 * write to themselves, so {@code simulate > full-disk} left a truncated log with exit 0, and {@code watch --json}
 * followed for ever after its reader had gone. This writer keeps the first failure ({@link #failure()}), tells
 * whoever asked ({@link #onFailure}, so that watch stops), and {@link #settle} turns it into one line and exit
 * {@value ExitCodes#BAD_INPUT}.
 */
final class Stdout extends PrintWriter {

    private final Sink sink;

    private Stdout(Sink sink) {
        super(new BufferedWriter(new OutputStreamWriter(new BufferedOutputStream(sink, 1 << 13), charset())), true);
        this.sink = sink;
    }

    /** The process's standard output, in the encoding picocli would use. */
    static Stdout open() {
        return new Stdout(new Sink(new FileOutputStream(FileDescriptor.out)));
    }

    /** What picocli writes standard output in: {@code sun.stdout.encoding} when set, else the default. */
    private static Charset charset() {
        String name = System.getProperty("sun.stdout.encoding");
        try {
            return name == null ? Charset.defaultCharset() : Charset.forName(name);
        } catch (IllegalCharsetNameException | UnsupportedCharsetException e) {
            return Charset.defaultCharset();
        }
    }

    /** The first write that failed, or null. */
    IOException failure() {
        return sink.failure;
    }

    /** From now on, {@code action} runs (once, on the writing thread) when a write fails; at once if one did. */
    void onFailure(Runnable action) {
        sink.onFailure = action;
        if (sink.failure != null) {
            action.run();
        }
    }

    /**
     * {@code code}, or {@value ExitCodes#BAD_INPUT} with one line on {@code err} when standard output could not be
     * written (what it shows is incomplete, so no success or verdict can stand). A code that already says the
     * command failed is left as it is.
     */
    int settle(int code, PrintWriter err) {
        flush();
        IOException e = sink.failure;
        if (e == null || code == ExitCodes.USAGE || code == ExitCodes.BAD_INPUT || code == ExitCodes.INTERNAL) {
            return code;
        }
        err.println("predmon: standard output: not written (" + BadInputException.reason(e)
                + "); what it shows is incomplete");
        err.flush();
        return ExitCodes.BAD_INPUT;
    }

    /** The bytes on their way to the file descriptor, the first failure kept. */
    private static final class Sink extends OutputStream {
        private final OutputStream out;
        private volatile IOException failure;
        private volatile Runnable onFailure;

        Sink(OutputStream out) {
            this.out = out;
        }

        @Override
        public void write(int b) throws IOException {
            write(new byte[] {(byte) b}, 0, 1);
        }

        @Override
        public void write(byte[] b, int off, int len) throws IOException {
            try {
                out.write(b, off, len);
            } catch (IOException e) {
                throw failed(e);
            }
        }

        @Override
        public void flush() throws IOException {
            try {
                out.flush();
            } catch (IOException e) {
                throw failed(e);
            }
        }

        private IOException failed(IOException e) {
            if (failure == null) {
                failure = e;
                Runnable action = onFailure;
                if (action != null) {
                    action.run();
                }
            }
            return e;
        }
    }
}
