package pod.mavlink.signing

import pod.core.PodException
import java.nio.file.Files
import java.nio.file.NoSuchFileException
import java.nio.file.Path
import java.nio.file.attribute.PosixFileAttributeView
import java.nio.file.attribute.PosixFilePermission

/**
 * A signing key could not be read. The message names the file or variable and what was wrong
 * with it (its size, its mode), never the key's bytes or any of the file's content.
 */
public class InvalidSigningKey(
    /** Where the key was looked for: a file path or `$POD_SIGNING_KEY`. */
    public val source: String,
    /** What was wrong with it. */
    public val reason: String,
) : PodException("signing key $source: $reason")

/**
 * Where Pod reads a MAVLink 2 signing key: a file or an environment variable, never the command
 * line (a key in an argument is in the shell's history and in every process listing).
 *
 * A key file holds either the 32 raw bytes of the key (exactly 32 bytes, as `head -c 32
 * /dev/urandom > pod.key` makes it) or the key as 64 hexadecimal digits (whitespace, a final newline
 * included, ignored; as `openssl rand -hex 32 > pod.key` makes it). On a POSIX file system a file
 * that its group or others may read is refused, as ssh refuses such a private key: keep it 0600.
 * The environment variable holds the 64 hexadecimal digits.
 */
public object SigningKeys {
    /** The environment variable read for a key when no key file is given. */
    public const val ENVIRONMENT_VARIABLE: String = "POD_SIGNING_KEY"

    /** The key in the file at [path]; throws [InvalidSigningKey] when it is missing, open to others, or malformed. */
    public fun fromFile(path: Path): SigningKey {
        val source = path.toString()
        val bytes = try {
            Files.readAllBytes(path)
        } catch (e: NoSuchFileException) {
            throw InvalidSigningKey(source, "no such file")
        } catch (e: java.io.IOException) {
            throw InvalidSigningKey(source, "cannot be read (${e.javaClass.simpleName})")
        }
        try {
            requirePrivate(path, source)
            if (bytes.size == SigningKey.SIZE) return SigningKey(bytes)
            val text = String(bytes, Charsets.US_ASCII).filterNot { it.isWhitespace() }
            if (text.length != SigningKey.SIZE * 2 || !text.all { it.isHexDigit() }) {
                throw InvalidSigningKey(source, "expected 32 raw bytes or 64 hexadecimal digits, found ${bytes.size} bytes that are neither")
            }
            return SigningKey.fromHex(text)
        } finally {
            bytes.fill(0)
        }
    }

    /** The key in [value], the content of [variable]: 64 hexadecimal digits; throws [InvalidSigningKey] otherwise. */
    public fun fromHexVariable(value: String, variable: String = ENVIRONMENT_VARIABLE): SigningKey {
        val text = value.filterNot { it.isWhitespace() }
        if (text.length != SigningKey.SIZE * 2 || !text.all { it.isHexDigit() }) {
            throw InvalidSigningKey("\$$variable", "expected 64 hexadecimal digits, found ${text.length} characters that are not")
        }
        return SigningKey.fromHex(text)
    }

    /**
     * The key from [file] when one is given, else from [environment]'s [ENVIRONMENT_VARIABLE] when
     * set and not blank, else null (the link is not signed).
     */
    public fun resolve(file: Path?, environment: Map<String, String> = System.getenv()): SigningKey? = when {
        file != null -> fromFile(file)
        !environment[ENVIRONMENT_VARIABLE].isNullOrBlank() -> fromHexVariable(environment.getValue(ENVIRONMENT_VARIABLE))
        else -> null
    }

    private fun requirePrivate(path: Path, source: String) {
        val view = Files.getFileAttributeView(path, PosixFileAttributeView::class.java) ?: return
        val open = view.readAttributes().permissions().filter { it in OPEN_TO_OTHERS }
        if (open.isNotEmpty()) throw InvalidSigningKey(source, "readable or writable by others (${open.joinToString { it.name.lowercase() }}): chmod 600 it")
    }

    private fun Char.isHexDigit(): Boolean = this in '0'..'9' || this in 'a'..'f' || this in 'A'..'F'

    private val OPEN_TO_OTHERS = setOf(
        PosixFilePermission.GROUP_READ, PosixFilePermission.GROUP_WRITE,
        PosixFilePermission.OTHERS_READ, PosixFilePermission.OTHERS_WRITE,
    )
}
