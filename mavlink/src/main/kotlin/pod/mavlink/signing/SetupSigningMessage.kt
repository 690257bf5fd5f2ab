package pod.mavlink.signing

import io.dronefleet.mavlink.common.SetupSigning
import java.math.BigInteger

/**
 * SETUP_SIGNING (id 256) giving [this] key to [targetSystem]/[targetComponent], its timestamp
 * starting at [initialTimestamp] (10 µs units since 2015): the one message a key's bytes go into
 * besides a signature's hash. It crosses the link in the clear, so send it only over a link the
 * operator trusts, and do not record that link meanwhile (a tlog would keep the key).
 *
 * ArduPilot stores the key with the timestamp and uses both at once on every link; a key of 32
 * zero bytes with timestamp 0 ([disableSigning]) turns signing off (ArduPilot/ardupilot
 * libraries/GCS_MAVLink/GCS_Signing.cpp, handle_setup_signing and load_signing_key).
 */
public fun SigningKey.setupMessage(targetSystem: Int, targetComponent: Int, initialTimestamp: Long): SetupSigning =
    SetupSigning.builder().targetSystem(targetSystem).targetComponent(targetComponent)
        .secretKey(secret.copyOf()).initialTimestamp(BigInteger.valueOf(initialTimestamp)).build()

/** SETUP_SIGNING with an all-zero key and timestamp 0: ArduPilot then stops signing and checking (MAVProxy's `signing remove`). */
public fun disableSigning(targetSystem: Int, targetComponent: Int): SetupSigning =
    SetupSigning.builder().targetSystem(targetSystem).targetComponent(targetComponent)
        .secretKey(ByteArray(SigningKey.SIZE)).initialTimestamp(BigInteger.ZERO).build()
