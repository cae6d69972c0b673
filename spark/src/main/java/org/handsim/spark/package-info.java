/**
 * The Apache Spark engine of {@code handsim plan} and {@code handsim sweep}: the
 * indexed trials of a {@link org.handsim.plan.IndexedJob} as a Spark job, embedded
 * ({@code local[*]}) or on a standalone cluster ({@code spark://HOST:7077}). A subproject
 * ({@code spark/}) that depends on the core; the core finds it through
 * {@link java.util.ServiceLoader} when it is on the class path and never loads Spark otherwise.
 */
package org.handsim.spark;
