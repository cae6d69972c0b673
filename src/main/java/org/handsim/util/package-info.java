/**
 * Edge-of-the-program helpers with no numerics: a small JSON reader that reports line and
 * column, a JSON writer for the command outputs, CSV reading with line numbers, and atomic
 * file output (write to a temporary name, then rename) so that a failed run never leaves a
 * half-written file that looks complete.
 */
package org.handsim.util;
