// The classic cup of models/cup.kerf (radius 1.2, wall 0.12, 2.4 tall, a half-ring handle),
// standing on z instead of y, for the slicing benchmark (bench/run_slice_bench.sh). OpenSCAD
// cuts at z = 0, so the cup is lowered by the cut height H (mid height, 1.2); set $fn with -D.
R = 1.2;
wall = R / 10;
H = 1.2;

module cup() {
    union() {
        difference() {
            cylinder(h = 2.4, r = R);
            translate([0, 0, wall]) cylinder(h = 2.5 - wall, r = R - wall);
        }
        // The handle: a ring about the y axis (0.5 < radius < 0.7, 0.2 thick), its x <= 0 half cut.
        translate([R - 0.05, 0, 1.2]) difference() {
            rotate([90, 0, 0]) cylinder(h = 0.2, r = 0.7, center = true);
            rotate([90, 0, 0]) cylinder(h = 0.4, r = 0.5, center = true);
            translate([-1, -1, -1]) cube([1, 2, 2]);
        }
    }
}

projection(cut = true) translate([0, 0, -H]) cup();
