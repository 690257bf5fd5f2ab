package pod.mavlink.link

/** A link could not be opened or broke; [message] says which link and why. */
public open class LinkException(message: String, cause: Throwable? = null) : pod.core.PodException(message, cause)

/** A connection string that does not parse; [reason] says what was expected. */
public class InvalidConnectionString(
    /** The text as given. */
    public val text: String,
    /** What is wrong with it. */
    public val reason: String,
) : LinkException("invalid connection string '$text': $reason")

/** A local port that another socket already holds. */
public class PortInUse(
    /** The address we tried to bind. */
    public val address: LinkAddress,
    cause: Throwable? = null,
) : LinkException("cannot listen on ${address.hostAndPort}: the port is already in use", cause)

/** A host name that does not resolve, or a remote that refuses or cannot be reached. */
public class HostUnreachable(
    /** The address we tried to reach. */
    public val address: LinkAddress,
    /** What the operating system said. */
    public val reason: String,
    cause: Throwable? = null,
) : LinkException("cannot reach ${address.hostAndPort}: $reason", cause)
