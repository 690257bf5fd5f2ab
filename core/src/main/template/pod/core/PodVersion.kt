package pod.core

/**
 * The version of Pod these classes were built as (`0.1.0`): the one version every `pod-*` artifact
 * and `pod-bom` share. The build writes it here from `.mvn/maven.config`.
 */
public const val POD_VERSION: String = "${project.version}"
