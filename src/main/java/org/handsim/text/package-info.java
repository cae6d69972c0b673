/**
 * Text formats at the program's edges: the JSON reader and writer, the one number format of every
 * output ({@link org.handsim.text.Decimal}) and input quoted safely in one-line messages
 * ({@link org.handsim.text.SafeText}). It uses the JDK and jackson-core alone, and no other room.
 */
package org.handsim.text;
