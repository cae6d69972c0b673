/**
 * Grasp planning: seeded hand poses around an object ({@link org.handsim.plan.TrialSampler}),
 * GraspIt!-style autograsp — approach until the palm or a finger meets the object
 * ({@link org.handsim.plan.Autograsp}), then close every finger with the clutch model until it
 * stalls — and the grasp's evaluation (force closure, ε, volume, minimum hold), one trial per
 * index ({@link org.handsim.plan.TrialRunner}); engine-neutral: a {@link org.handsim.plan.TrialEngine}
 * runs the indexed trials (threads here, Apache Spark in the {@code spark/} subproject) and
 * {@link org.handsim.plan.PlanOutput} streams the table.
 *
 * <p>May use every room below it (docs/DESIGN.md, "Modules").
 */
package org.handsim.plan;
