package org.handsim.math;

import org.handsim.model.HandModel;

/** A fixture of LayersTest: a room low in the table that reaches up to the model. */
class Upward {
    HandModel model;
}
