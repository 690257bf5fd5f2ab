package pod.cli

import com.github.ajalt.mordant.terminal.Terminal

/**
 * An [Output] on a Mordant [terminal]: lines are printed through it, so that a live table or a
 * progress bar being drawn stays below them, and views may draw on it while it is interactive
 * ([liveTerminal]).
 */
internal class TerminalOutput(val terminal: Terminal) : Output {
    override fun line(text: String) = terminal.println(text)

    companion object {
        /**
         * Standard output for people: a [TerminalOutput] when it is an interactive terminal,
         * otherwise plain lines (a pipe or a file gets no escape codes and nothing redrawn).
         */
        fun standard(): Output {
            val terminal = Terminal()
            return if (terminal.terminalInfo.outputInteractive) TerminalOutput(terminal) else Output { println(it) }
        }
    }
}

/**
 * The terminal on which views may draw in place and in colour (live table, progress bars), or
 * null when this output takes plain lines only: not a terminal, or not an interactive one (Mordant
 * moves the cursor only when both input and output are a terminal).
 */
internal val Output.liveTerminal: Terminal?
    get() = (this as? TerminalOutput)?.terminal?.takeIf { it.terminalInfo.interactive }
