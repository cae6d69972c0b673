/**
 * Text formats at the program's edges: the JSON reader and writer, the one number format of every
 * output ({@link org.handsim.text.Decimal}) and input quoted safely in one-line messages
 * ({@link org.handsim.text.SafeText}).
 *
 * <p>May use no other room: the JDK and jackson-core only (docs/DESIGN.md, "Modules").
 */
package org.handsim.text;
