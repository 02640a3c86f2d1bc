package dev.predmon.rosbag;

import com.github.luben.zstd.Zstd;
import com.github.luben.zstd.ZstdException;
import net.jpountz.lz4.LZ4FrameInputStream;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.util.zip.CRC32;

/**
 * Decompresses the records of an MCAP chunk ({@code ""}, {@code "zstd"} or {@code "lz4"}, the LZ4 frame format) and
 * checks them against the chunk's CRC-32 where one is written. The uncompressed size the chunk declares is checked
 * before anything is allocated: it cannot exceed what its compressed bytes can expand to, nor a quarter of the heap.
 */
final class Chunks {

    /** A chunk whose records cannot be had; the message says what was expected. */
    static final class Bad extends Exception {
        private static final long serialVersionUID = 1L;

        Bad(String message) {
            super(message);
        }
    }

    /** Largest expansion of the formats: LZ4 at most 255:1; zstd's RLE blocks reach 128 KiB from 4 bytes. */
    private static final long LZ4_RATIO = 256;
    private static final long ZSTD_RATIO = 32_768;

    private Chunks() {
    }

    /** The uncompressed records of a chunk whose compressed records are {@code data[offset, offset + length)}. */
    static byte[] records(String compression, byte[] data, int offset, int length, long uncompressedSize, long crc)
            throws Bad {
        long ratio = switch (compression) {
            case "" -> 1;
            case "zstd" -> ZSTD_RATIO;
            case "lz4" -> LZ4_RATIO;
            default -> throw new Bad("expected the compression \"\", \"zstd\" or \"lz4\", found \"" + compression
                    + "\"");
        };
        long limit = Math.min(Math.min((long) length * ratio + 64, Integer.MAX_VALUE - 16),
                Runtime.getRuntime().maxMemory() / 4);
        if (uncompressedSize < 0 || uncompressedSize > limit) {
            throw new Bad("impossible uncompressed size " + Long.toUnsignedString(uncompressedSize) + " for "
                    + length + " byte(s) of " + (compression.isEmpty() ? "uncompressed" : compression) + " records");
        }
        int size = (int) uncompressedSize;
        byte[] out;
        switch (compression) {
            case "" -> {
                if (size != length) {
                    throw new Bad("expected " + size + " byte(s) of uncompressed records, found " + length);
                }
                out = new byte[size];
                System.arraycopy(data, offset, out, 0, size);
            }
            case "zstd" -> out = zstd(data, offset, length, size);
            default -> out = lz4(data, offset, length, size);
        }
        if (crc != 0) {
            CRC32 c = new CRC32();
            c.update(out, 0, out.length);
            if (c.getValue() != crc) {
                throw new Bad(String.format("bad CRC: the records' CRC-32 is %08x, the chunk says %08x",
                        c.getValue(), crc));
            }
        }
        return out;
    }

    private static byte[] zstd(byte[] data, int offset, int length, int size) throws Bad {
        byte[] out = new byte[size];
        long n;
        try {
            n = Zstd.decompressByteArray(out, 0, size, data, offset, length);
        } catch (ZstdException e) {
            throw new Bad("expected zstd-compressed records of " + size + " byte(s): " + e.getMessage());
        }
        if (Zstd.isError(n) || n != size) {
            throw new Bad("expected zstd-compressed records of " + size + " byte(s), "
                    + (Zstd.isError(n) ? "zstd says: " + Zstd.getErrorName(n) : "they hold " + n));
        }
        return out;
    }

    private static byte[] lz4(byte[] data, int offset, int length, int size) throws Bad {
        byte[] out = new byte[size];
        try (InputStream in = new LZ4FrameInputStream(new ByteArrayInputStream(data, offset, length))) {
            int n = in.readNBytes(out, 0, size);
            if (n != size || in.read() != -1) {
                throw new Bad("expected lz4-compressed records of " + size + " byte(s), they hold "
                        + (n != size ? n : "more"));
            }
        } catch (IOException | RuntimeException e) {
            throw new Bad("expected lz4-compressed records (LZ4 frame format) of " + size + " byte(s): "
                    + e.getMessage());
        }
        return out;
    }
}
