/**
 * Files in and out: the one gate every input file passes ({@link org.handsim.files.InputFile}:
 * regular files only, size and line limits, UTF-8), CSV input, atomic output files and output
 * folders published whole ({@link org.handsim.files.OutputSet}), and folders only the user may
 * write.
 *
 * <p>May use {@code process} and {@code text} (docs/DESIGN.md, "Modules").
 */
package org.handsim.files;
