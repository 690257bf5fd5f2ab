package pod.cli.gcs

/** A page's request that cannot be carried out as asked (bad argument, unknown vehicle); its message is the reply's error. */
public class GcsRequestException(message: String) : pod.core.PodException(message)
