package pod.e2e

import org.jetbrains.kotlin.CoreEnvironmentDeprecation
import org.jetbrains.kotlin.cli.extensionsStorage
import org.jetbrains.kotlin.cli.jvm.compiler.EnvironmentConfigFiles
import org.jetbrains.kotlin.cli.jvm.compiler.KotlinCoreEnvironment
import org.jetbrains.kotlin.com.intellij.openapi.util.Disposer
import org.jetbrains.kotlin.com.intellij.psi.PsiErrorElement
import org.jetbrains.kotlin.com.intellij.psi.util.PsiTreeUtil
import org.jetbrains.kotlin.compiler.plugin.CompilerPluginRegistrar
import org.jetbrains.kotlin.compiler.plugin.ExperimentalCompilerApi
import org.jetbrains.kotlin.config.CompilerConfiguration
import org.jetbrains.kotlin.kdoc.psi.api.KDoc
import org.jetbrains.kotlin.kdoc.psi.impl.KDocTag
import org.jetbrains.kotlin.lexer.KtTokens
import org.jetbrains.kotlin.psi.KtClass
import org.jetbrains.kotlin.psi.KtClassOrObject
import org.jetbrains.kotlin.psi.KtDeclaration
import org.jetbrains.kotlin.psi.KtEnumEntry
import org.jetbrains.kotlin.psi.KtFile
import org.jetbrains.kotlin.psi.KtNamedDeclaration
import org.jetbrains.kotlin.psi.KtNamedFunction
import org.jetbrains.kotlin.psi.KtObjectDeclaration
import org.jetbrains.kotlin.psi.KtParameter
import org.jetbrains.kotlin.psi.KtProperty
import org.jetbrains.kotlin.psi.KtPsiFactory
import org.jetbrains.kotlin.psi.KtSecondaryConstructor
import org.jetbrains.kotlin.psi.KtTypeAlias

/** A public declaration a reader of the API site would find without a word of KDoc. */
data class Undocumented(val file: String, val line: Int, val what: String) {
    override fun toString(): String = "$file:$line $what"
}

/**
 * Finds the public API of Kotlin sources that has no KDoc, by parsing them with the Kotlin
 * compiler's PSI (no resolution, so no class path: a file is judged by its own text).
 *
 * A declaration is API when it is public (or protected in an open, abstract or sealed class) and
 * every class around it is too; local declarations and `override`s (which inherit their docs) are
 * not. A constructor `val`/`var` counts as documented by its own KDoc or by a `@property` or
 * `@param` tag of its class's KDoc. A KDoc whose description is blank does not count. Primary
 * constructors are described by their class, as Dokka does; secondary constructors are API.
 */
class KDocCoverage : AutoCloseable {
    private val disposable = Disposer.newDisposable("KDocCoverage")

    // The compiler's own entry to a PSI project; it is marked for rework, and we only parse with it.
    @OptIn(CompilerConfiguration.Internals::class, CoreEnvironmentDeprecation::class, ExperimentalCompilerApi::class)
    private val psi: KtPsiFactory = run {
        val configuration = CompilerConfiguration()
        configuration.extensionsStorage = CompilerPluginRegistrar.ExtensionStorage() // no compiler plugins
        val environment = KotlinCoreEnvironment.createForProduction(disposable, configuration, EnvironmentConfigFiles.JVM_CONFIG_FILES)
        KtPsiFactory(environment.project, markGenerated = false)
    }

    /** [text] parsed as the Kotlin file [name]. */
    fun parse(name: String, text: String): KtFile = psi.createFile(name, text)

    /**
     * Where [file]'s code does not parse: a declaration after a syntax error could be missed by
     * [undocumented], so a file must parse cleanly to be judged (a slip inside a KDoc hides nothing).
     */
    fun syntaxErrors(file: KtFile, path: String): List<String> =
        PsiTreeUtil.findChildrenOfType(file, PsiErrorElement::class.java).filter { PsiTreeUtil.getParentOfType(it, KDoc::class.java) == null }.map { error ->
            "$path:${lineOf(file, error.textOffset)} ${error.errorDescription}"
        }

    /** Whether [file] declares any API at top level (its package then needs an overview). */
    fun hasApi(file: KtFile): Boolean = file.declarations.any { isApi(it, parent = null) }

    /** Every API declaration of [file] without KDoc, named by [path] in the result. */
    fun undocumented(file: KtFile, path: String): List<Undocumented> {
        val found = ArrayList<Undocumented>()
        fun report(declaration: KtDeclaration, what: String) {
            found += Undocumented(path, lineOf(file, declaration.textOffset), what)
        }

        fun visit(declaration: KtDeclaration, parent: KtClassOrObject?, prefix: String) {
            if (!isApi(declaration, parent)) return
            val name = prefix + ((declaration as? KtNamedDeclaration)?.name ?: "<anonymous>")
            if (!described(declaration.docComment)) report(declaration, "${kind(declaration)} $name")
            if (declaration !is KtClassOrObject || declaration is KtEnumEntry) return
            val tagged = documentedParameters(declaration.docComment)
            for (parameter in declaration.primaryConstructorParameters) {
                if (!parameter.hasValOrVar() || !isApi(parameter, declaration)) continue
                if (parameter.name !in tagged && !described(parameter.docComment)) {
                    report(parameter, "${if (parameter.isMutable) "var" else "val"} $name.${parameter.name}")
                }
            }
            declaration.declarations.forEach { visit(it, declaration, "$name.") }
        }
        file.declarations.forEach { visit(it, parent = null, prefix = "") }
        return found
    }

    /**
     * Whether a reader of the API sees [declaration]: public by default or by its modifier,
     * protected only where a subclass can reach it, never an `override` (documented where it is
     * declared). Callers descend only through API classes, so the parents are API too.
     */
    private fun isApi(declaration: KtDeclaration, parent: KtClassOrObject?): Boolean {
        if (declaration.hasModifier(KtTokens.OVERRIDE_KEYWORD)) return false
        if (declaration.hasModifier(KtTokens.PRIVATE_KEYWORD) || declaration.hasModifier(KtTokens.INTERNAL_KEYWORD)) return false
        if (declaration.hasModifier(KtTokens.PROTECTED_KEYWORD)) {
            val extensible = parent is KtClass && (parent.isInterface() || listOf(KtTokens.OPEN_KEYWORD, KtTokens.ABSTRACT_KEYWORD, KtTokens.SEALED_KEYWORD).any { parent.hasModifier(it) })
            if (!extensible) return false
        }
        return declaration is KtClassOrObject || declaration is KtNamedFunction || declaration is KtProperty ||
            declaration is KtTypeAlias || declaration is KtSecondaryConstructor || declaration is KtParameter
    }

    /** The line (from 1) of [file] that [offset] falls on. */
    private fun lineOf(file: KtFile, offset: Int): Int = file.text.substring(0, offset).count { it == '\n' } + 1

    private fun kind(declaration: KtDeclaration): String = when (declaration) {
        is KtEnumEntry -> "enum entry"
        is KtObjectDeclaration -> if (declaration.isCompanion()) "companion object" else "object"
        is KtClass -> if (declaration.isInterface()) "interface" else "class"
        is KtNamedFunction -> "fun"
        is KtProperty -> if (declaration.isVar) "var" else "val"
        is KtTypeAlias -> "typealias"
        is KtSecondaryConstructor -> "constructor"
        else -> "declaration"
    }

    /** Whether [doc] says something before its tags: a KDoc of tags alone does not describe a declaration. */
    private fun described(doc: KDoc?): Boolean = doc != null && doc.getDefaultSection().getContent().isNotBlank()

    /** The names the `@property` and `@param` tags of [doc] describe (with words, not just the name). */
    private fun documentedParameters(doc: KDoc?): Set<String> {
        if (doc == null) return emptySet()
        return PsiTreeUtil.findChildrenOfType(doc, KDocTag::class.java)
            .filter { it.name == "property" || it.name == "param" }
            .filter { it.getContent().isNotBlank() }
            .mapNotNull { it.getSubjectName() }
            .toSet()
    }

    override fun close() {
        Disposer.dispose(disposable)
    }
}
