package pod.cli

import com.github.ajalt.clikt.core.CliktCommand
import com.github.ajalt.clikt.parameters.options.option
import com.github.ajalt.clikt.parameters.types.path
import pod.mavlink.GroundStationConfig
import pod.mavlink.signing.InvalidSigningKey
import pod.mavlink.signing.LinkSigning
import pod.mavlink.signing.SigningKey
import pod.mavlink.signing.SigningKeys
import java.nio.file.Path

/** Help of `--key-file`, the same on every command that takes it. */
internal const val KEY_FILE_HELP: String =
    "sign the link (MAVLink 2) with the key in this file: 32 raw bytes or 64 hex digits, mode 0600 " +
        "(default: the key in \$${SigningKeys.ENVIRONMENT_VARIABLE}, 64 hex digits; neither: unsigned)"

/** `--key-file K`: the signing key's file; see [signingKey]. */
internal fun CliktCommand.keyFileOption() = option("--key-file", metavar = "K", help = KEY_FILE_HELP).path()

/**
 * The signing key from [keyFile], else from `$POD_SIGNING_KEY`, else null; a malformed key ends
 * the command with a usage error naming the file or variable (never the key).
 */
internal fun signingKey(keyFile: Path?): SigningKey? = try {
    SigningKeys.resolve(keyFile)
} catch (e: InvalidSigningKey) {
    badInput(e.message ?: "bad signing key")
}

/**
 * [base] signed with [key] on [linkId] (unsigned frames refused but radio reports), or [base] when
 * there is no key.
 */
internal fun signedConfig(key: SigningKey?, base: GroundStationConfig = GroundStationConfig(), linkId: Int = COMMAND_LINK_ID): GroundStationConfig =
    if (key == null) base else base.copy(signing = LinkSigning(key, linkId))

/**
 * The signing link id of the commands that come and go (`pod arm`, `pod mission …`, `pod run`).
 * A vehicle keeps one signing stream per system, component and link id, whose timestamp must grow
 * (ArduPilot, mavlink_helpers.h `mavlink_signature_check`), and at most 16 of them until it
 * reboots: every `pod` process shares system 255, component 190, so each kind of process keeps
 * one fixed link id, and only processes that run side by side get different ones.
 */
internal const val COMMAND_LINK_ID: Int = 0

/** `pod watch`'s signing link id: it runs beside the commands, whose frames must not look like replays of its own. */
internal const val WATCH_LINK_ID: Int = 1

