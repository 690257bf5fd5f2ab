package pod.cli.script

import java.io.File
import kotlin.script.experimental.api.ResultWithDiagnostics
import kotlin.script.experimental.api.SourceCode
import kotlin.script.experimental.api.asSuccess
import kotlin.script.experimental.dependencies.ArtifactWithLocation
import kotlin.script.experimental.dependencies.ExternalDependenciesResolver
import kotlin.script.experimental.dependencies.RepositoryCoordinates

/**
 * Resolves `@file:DependsOn` as [resolver] does, except Pod's own artifacts (`pod:…`), which
 * `pod run` has already put on the script's classpath. A script written for plain `kotlin`
 * (`@file:DependsOn("pod:pod-dsl:0.1.0")`) thus runs under `pod run` before anything is
 * installed, and never mixes an older installed Pod with the one running it.
 */
internal class PodArtifactsProvided(private val resolver: ExternalDependenciesResolver) : ExternalDependenciesResolver {
    override fun acceptsRepository(repositoryCoordinates: RepositoryCoordinates): Boolean =
        resolver.acceptsRepository(repositoryCoordinates)

    override fun addRepository(
        repositoryCoordinates: RepositoryCoordinates,
        options: ExternalDependenciesResolver.Options,
        sourceCodeLocation: SourceCode.LocationWithId?,
    ): ResultWithDiagnostics<Boolean> = resolver.addRepository(repositoryCoordinates, options, sourceCodeLocation)

    override fun acceptsArtifact(artifactCoordinates: String): Boolean =
        isPod(artifactCoordinates) || resolver.acceptsArtifact(artifactCoordinates)

    override suspend fun resolve(
        artifactCoordinates: String,
        options: ExternalDependenciesResolver.Options,
        sourceCodeLocation: SourceCode.LocationWithId?,
    ): ResultWithDiagnostics<List<File>> =
        if (isPod(artifactCoordinates)) emptyList<File>().asSuccess() else resolver.resolve(artifactCoordinates, options, sourceCodeLocation)

    override suspend fun resolve(
        artifactsWithLocations: List<ArtifactWithLocation>,
        options: ExternalDependenciesResolver.Options,
    ): ResultWithDiagnostics<List<File>> {
        val others = artifactsWithLocations.filterNot { isPod(it.artifact) }
        return if (others.isEmpty()) emptyList<File>().asSuccess() else resolver.resolve(others, options)
    }

    private fun isPod(coordinates: String) = coordinates.trim().startsWith("pod:")
}
