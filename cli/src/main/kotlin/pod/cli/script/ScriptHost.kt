package pod.cli.script

import org.jetbrains.kotlin.mainKts.MainKtsConfigurator
import org.jetbrains.kotlin.mainKts.MainKtsEvaluationConfiguration
import org.jetbrains.kotlin.mainKts.MainKtsScript
import pod.launch.ProgramLocation
import java.io.File
import kotlin.script.experimental.api.EvaluationResult
import kotlin.script.experimental.api.RefineConfigurationOnAnnotationsData
import kotlin.script.experimental.api.ResultValue
import kotlin.script.experimental.api.ResultWithDiagnostics
import kotlin.script.experimental.api.ScriptCompilationConfiguration
import kotlin.script.experimental.api.ScriptDiagnostic
import kotlin.script.experimental.api.ScriptEvaluationConfiguration
import kotlin.script.experimental.api.refineConfigurationOnAnnotations
import kotlin.script.experimental.api.hostConfiguration
import kotlin.script.experimental.api.with
import kotlin.script.experimental.host.with
import kotlin.script.experimental.jvm.CompiledJvmScriptsCache
import kotlin.script.experimental.jvm.compilationCache
import kotlin.script.experimental.host.toScriptSource
import kotlin.script.experimental.jvm.baseClassLoader
import kotlin.script.experimental.jvm.jvm
import kotlin.script.experimental.jvm.mainArguments
import kotlin.script.experimental.jvm.updateClasspath
import kotlin.script.experimental.jvmhost.BasicJvmScriptingHost
import kotlin.script.experimental.jvmhost.createJvmCompilationConfigurationFromTemplate

/** How a script run ended. */
internal sealed interface ScriptOutcome {
    /** The script ran to its end. */
    data object Completed : ScriptOutcome

    /** The compiler refused the script; [messages] are `file:line:column: error: …` lines. */
    data class CompileFailed(val messages: List<String>) : ScriptOutcome

    /** The script threw [error]; [line] is where in the script, when the stack trace says. */
    data class Threw(val error: Throwable, val line: Int?) : ScriptOutcome
}

/**
 * Compiles and runs `.main.kts` scripts in this JVM, with [classpath] (Pod and its dependencies)
 * on the script's classpath. Scripts are compiled as kotlin-main-kts compiles them, so
 * `@file:DependsOn`, `@file:Repository` and `@file:Import` work; a `@file:DependsOn` on Pod's own
 * artifacts (group `pod`) is skipped because they are already there.
 */
internal class ScriptHost(private val classpath: List<File>, private val cacheDirectory: File? = CompiledScripts.directory()) {
    /**
     * Compiles [script] (unless a compiled copy is cached; [compiling] is told when it is not, as
     * that takes seconds) and runs it with [args]; compiler warnings go to [warn].
     */
    fun run(script: File, args: List<String>, compiling: () -> Unit = {}, warn: (String) -> Unit): ScriptOutcome {
        val result = BasicJvmScriptingHost().eval(script.toScriptSource(), compilation(compiling), evaluation(args))
        result.reports.filter { it.severity == ScriptDiagnostic.Severity.WARNING }.forEach { warn(render(it, script)) }
        return when (result) {
            is ResultWithDiagnostics.Failure -> ScriptOutcome.CompileFailed(
                result.reports.filter { it.severity >= ScriptDiagnostic.Severity.ERROR }.map { render(it, script) }
                    .ifEmpty { listOf("${script.path}: error: the script could not be compiled") },
            )
            is ResultWithDiagnostics.Success -> outcome(result.value, script)
        }
    }

    private fun compilation(compiling: () -> Unit): ScriptCompilationConfiguration {
        val base = createJvmCompilationConfigurationFromTemplate<MainKtsScript>()
        val refinements = base[ScriptCompilationConfiguration.refineConfigurationOnAnnotations].orEmpty().map { data ->
            val handler = data.handler
            if (handler is MainKtsConfigurator) {
                RefineConfigurationOnAnnotationsData(data.annotations, handler.transformResolver { PodArtifactsProvided(it) })
            } else {
                data
            }
        }
        return base.with {
            updateClasspath(classpath)
            refineConfigurationOnAnnotations.put(refinements)
            // Replaces kotlin-main-kts' cache (see CompiledScripts for why).
            hostConfiguration.update { host ->
                host.with {
                    jvm {
                        val cache = if (cacheDirectory == null) CompiledJvmScriptsCache.NoCache else CompiledScripts.cache(cacheDirectory)
                        compilationCache(CompiledScripts.noticingMisses(cache, compiling))
                    }
                }
            }
        }
    }

    private fun evaluation(args: List<String>): ScriptEvaluationConfiguration =
        ScriptEvaluationConfiguration(MainKtsEvaluationConfiguration) {
            jvm {
                // Parent-first from the CLI's own loader: the script and `pod run` share Pod's classes.
                baseClassLoader(ScriptHost::class.java.classLoader)
                mainArguments(args.toTypedArray())
            }
        }

    private fun outcome(evaluation: EvaluationResult, script: File): ScriptOutcome =
        when (val value = evaluation.returnValue) {
            is ResultValue.Error -> ScriptOutcome.Threw(value.error, lineOf(value.error, script))
            else -> ScriptOutcome.Completed
        }

    /**
     * The script's line that failed: where a `pod { }` program was suspended when Pod failed its
     * call ([ProgramLocation]), else the deepest frame of the script in the stack trace.
     */
    private fun lineOf(error: Throwable, script: File): Int? {
        val frame = ProgramLocation.of(error)?.takeIf { it.fileName == script.name }
            ?: error.stackTrace.firstOrNull { it.fileName == script.name }
        return frame?.lineNumber?.takeIf { it > 0 }
    }

    private fun render(d: ScriptDiagnostic, script: File): String {
        val where = buildString {
            append(d.sourcePath ?: script.path)
            d.location?.start?.let { append(":${it.line}:${it.col}") }
        }
        val severity = d.severity.name.lowercase()
        return "$where: $severity: ${d.message}"
    }
}
