package pod.test

/** The version of pod-test this is: that of the Pod modules it tests. */
public val podTestVersion: String get() = pod.core.POD_VERSION
