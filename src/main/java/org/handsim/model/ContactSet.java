package org.handsim.model;

import java.util.Arrays;

/**
 * The point contacts of one finger with the object in one step, on primitive arrays, in the
 * world frame: centre p (m), unit normal n of the object surface pointing out of the object,
 * patch area (m²), the link (1..3) it is on, and, once solved, the force the finger applies to
 * the object — its vector (N, world; along −n without friction, inside the friction cone about
 * −n with it) and magnitude — and whether it was undetermined (DESIGN.md decisions 2, 3, 5).
 * Reused from step to step: {@link #clear()} keeps capacity.
 */
public final class ContactSet {
    private int n;
    double[] points = new double[24];
    double[] normals = new double[24];
    double[] pushDirs = new double[24];
    double[] areas = new double[8];
    int[] links = new int[8];
    double[] forces = new double[8];
    double[] forceVectors = new double[24];
    boolean[] undetermined = new boolean[8];

    public void clear() { n = 0; }

    /** Adds a contact; returns its index. */
    public int add(int link, double px, double py, double pz, double nx, double ny, double nz, double area) {
        if (n == links.length) {
            int c = 2 * n;
            points = Arrays.copyOf(points, 3 * c);
            normals = Arrays.copyOf(normals, 3 * c);
            pushDirs = Arrays.copyOf(pushDirs, 3 * c);
            areas = Arrays.copyOf(areas, c);
            links = Arrays.copyOf(links, c);
            forces = Arrays.copyOf(forces, c);
            forceVectors = Arrays.copyOf(forceVectors, 3 * c);
            undetermined = Arrays.copyOf(undetermined, c);
        }
        points[3 * n] = px; points[3 * n + 1] = py; points[3 * n + 2] = pz;
        normals[3 * n] = nx; normals[3 * n + 1] = ny; normals[3 * n + 2] = nz;
        pushDirs[3 * n] = -nx; pushDirs[3 * n + 1] = -ny; pushDirs[3 * n + 2] = -nz;
        areas[n] = area;
        links[n] = link;
        forces[n] = 0;
        forceVectors[3 * n] = 0; forceVectors[3 * n + 1] = 0; forceVectors[3 * n + 2] = 0;
        undetermined[n] = false;
        return n++;
    }

    /** Appends the contacts of another set (geometry only; forces start at 0). */
    public void append(ContactSet o) {
        for (int i = 0; i < o.n; i++) {
            add(o.links[i], o.points[3 * i], o.points[3 * i + 1], o.points[3 * i + 2],
                o.normals[3 * i], o.normals[3 * i + 1], o.normals[3 * i + 2], o.areas[i]);
        }
    }

    public int size() { return n; }
    public int link(int i) { return links[i]; }
    /** Magnitude of contact i's force, N. */
    public double force(int i) { return forces[i]; }
    /** The force contact i's finger applies to the object, world frame, N (a new array). */
    public double[] forceVector(int i) { return new double[] {forceVectors[3 * i], forceVectors[3 * i + 1], forceVectors[3 * i + 2]}; }
    public boolean undetermined(int i) { return undetermined[i]; }
    public double area(int i) { return areas[i]; }
    /** Contact point i, world frame (a new array). */
    public double[] point(int i) { return new double[] {points[3 * i], points[3 * i + 1], points[3 * i + 2]}; }
    /** Outward object normal at contact i, world frame (a new array). */
    public double[] normal(int i) { return new double[] {normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]}; }

    /** @return true if some contact is on link j */
    public boolean touches(int link) {
        for (int i = 0; i < n; i++) if (links[i] == link) return true;
        return false;
    }

    /** @return the sum of the contact force magnitudes, N */
    public double forceSum() {
        double s = 0;
        for (int i = 0; i < n; i++) s += forces[i];
        return s;
    }
}
