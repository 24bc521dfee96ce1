// A cube with 1000 spherical voids, as models/voids.kerf: the cube [0, 10]^3 minus spheres of
// radius 0.4 at (i + 0.5, j + 0.5, k + 0.5), i, j, k in 0..9. Cut through the centres of the
// sixth layer, z = 5.5 (mid height falls between two layers and would cut no void); set $fn
// with -D.
H = 5.5;

projection(cut = true) translate([0, 0, -H]) difference() {
    cube([10, 10, 10]);
    for (i = [0 : 9], j = [0 : 9], k = [0 : 9])
        translate([i + 0.5, j + 0.5, k + 0.5]) sphere(r = 0.4);
}
