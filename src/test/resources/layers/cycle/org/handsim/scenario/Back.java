package org.handsim.scenario;

/** A fixture of LayersTest: the scenario naming the model that reads it (a cycle). */
class Back {
    org.handsim.model.HandModel model;   // a fully qualified name counts like an import
}
