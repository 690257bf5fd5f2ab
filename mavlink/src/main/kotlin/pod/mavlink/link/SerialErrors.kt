package pod.mavlink.link

/** No device at a serial address's path (nothing plugged in, a typo, a radio on another port). */
public class DeviceNotFound(
    /** The address we tried to open. */
    public val address: LinkAddress.Serial,
    cause: Throwable? = null,
) : LinkException("no serial device at ${address.path}", cause)

/**
 * A serial device that exists but cannot be opened: no permission (the user is not in the `dialout`
 * group), another program holds it, or the serial library could not load; [reason] says which.
 */
public class DeviceUnavailable(
    /** The address we tried to open. */
    public val address: LinkAddress.Serial,
    /** What went wrong, in words a user can act on. */
    public val reason: String,
    cause: Throwable? = null,
) : LinkException("cannot open serial device ${address.path}: $reason", cause)
