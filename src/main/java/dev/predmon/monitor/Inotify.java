package dev.predmon.monitor;

import com.sun.jna.Native;
import com.sun.jna.NativeLibrary;
import com.sun.jna.Platform;
import com.sun.jna.Pointer;

import java.io.IOException;
import java.nio.charset.Charset;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import java.nio.file.NotDirectoryException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Set;

/** Linux's inotify calls, through JNA, and what their errors mean. */
final class Inotify {

    /** The library these calls are bound to, once bound (JNA binds a class once); guarded by the class. */
    private static String bound;

    // The C library's calls that inotify takes, bound directly (JNA's direct mapping: a fraction of a microsecond
    // per call, where an interface's proxy takes several). size_t and ssize_t are longs: 64-bit platforms only.
    static native int inotify_init1(int flags);

    static native int inotify_add_watch(int fd, byte[] path, int mask);

    static native int inotify_rm_watch(int fd, int wd);

    static native long read(int fd, Pointer buf, long count);

    static native long write(int fd, Pointer buf, long count);

    static native int poll(Pointer fds, long nfds, int timeout);

    static native int eventfd(int initval, int flags);

    static native int close(int fd);

    static native Pointer strerror(int errnum);

    static final int IN_MODIFY = 0x2;
    static final int IN_ATTRIB = 0x4;
    static final int IN_MOVED_FROM = 0x40;
    static final int IN_MOVED_TO = 0x80;
    static final int IN_CREATE = 0x100;
    static final int IN_DELETE = 0x200;
    static final int IN_MOVE_SELF = 0x800;
    static final int IN_Q_OVERFLOW = 0x4000;
    static final int IN_IGNORED = 0x8000;
    static final int IN_ONLYDIR = 0x01000000;
    /** What a directory's watch asks for: as the JDK's, and its own move (the watch would follow it away). */
    static final int MASK = IN_MODIFY | IN_ATTRIB | IN_MOVED_FROM | IN_MOVED_TO | IN_CREATE | IN_DELETE
            | IN_MOVE_SELF | IN_ONLYDIR;
    /** {@code O_NONBLOCK} and {@code O_CLOEXEC}, as inotify_init1 and eventfd take them, on the architectures below. */
    static final int NONBLOCK = 0x800;
    static final int CLOEXEC = 0x80000;
    static final short POLLIN = 1;
    static final int EINTR = 4;
    static final int EAGAIN = 11;
    private static final int ENOENT = 2;
    private static final int EACCES = 13;
    private static final int ENOTDIR = 20;
    private static final int ENOSPC = 28;
    /** Where those flag values hold (asm-generic): not alpha, mips, parisc, sparc. */
    private static final Set<String> ARCHITECTURES = Set.of("x86-64", "aarch64", "ppc64le", "riscv64", "s390x",
            "loongarch64");
    /** How the JDK spells a path for the system, so that a directory is the one its Path names. */
    private static final Charset PATHS = Charset.forName(System.getProperty("sun.jnu.encoding",
            Charset.defaultCharset().name()));

    private Inotify() {
    }

    /**
     * Binds inotify's calls to the C library {@code library} through JNA, if not done yet; false where inotify cannot
     * be had this way (another system, a 32-bit one, JNA or the library not loadable, bound to another library).
     */
    static synchronized boolean bind(String library) {
        if (bound != null) {
            return bound.equals(library);
        }
        try {
            if (!Platform.isLinux() || !Platform.is64Bit() || !ARCHITECTURES.contains(Platform.ARCH)) {
                return false;
            }
            Native.register(Inotify.class, NativeLibrary.getInstance(library));
            bound = library;
            return true;
        } catch (LinkageError | RuntimeException e) {
            return false; // no native library for this platform, or none by that name: the JDK's watch service
        }
    }

    /** What the system says error {@code errno} is. */
    static String message(int errno) {
        Pointer p = strerror(errno);
        return p != null ? p.getString(0) : "error " + errno;
    }

    /** {@code path} as the system takes it: the JDK's spelling, ended by a NUL. */
    static byte[] spelling(Path path) {
        byte[] b = path.toString().getBytes(PATHS);
        return Arrays.copyOf(b, b.length + 1);
    }

    /** Decodes a file name as the JDK does, or null when the name would not be the same bytes as a Path. */
    static String name(byte[] bytes, int length) {
        String s = new String(bytes, 0, length, PATHS);
        byte[] back = s.getBytes(PATHS);
        return Arrays.equals(back, 0, back.length, bytes, 0, length) ? s : null;
    }

    /** The error of the last call on this thread. */
    static int errno() {
        return Native.getLastError();
    }

    /** Why inotify_add_watch failed for {@code dir}, as the JDK's watch service would say it. */
    static IOException registerFailed(Path dir, int errno) {
        return switch (errno) {
            case ENOSPC -> new IOException("User limit of inotify watches reached");
            case EACCES -> new AccessDeniedException(dir.toString());
            case ENOENT -> new NoSuchFileException(dir.toString());
            case ENOTDIR -> new NotDirectoryException(dir.toString());
            default -> new FileSystemException(dir.toString(), null, message(errno));
        };
    }
}
