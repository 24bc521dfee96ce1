// The cup of bench/mesh/cup.kerf in OpenSCAD (y up there, z up here: the cup's axis is z),
// for the STL export timing in bench/mesh/run_mesh_bench.sh. $fn is set on the command line.
R = 1.2;
wall = R / 10;
union() {
    difference() {
        cylinder(h = 2.4, r = R);
        translate([0, 0, wall]) cylinder(h = 2.5, r = R - wall);
    }
    // The handle: a half ring (x >= 0 after the move) 0.2 thick, centred at (R - 0.05, 1.2).
    translate([R - 0.05, 0, 1.2]) rotate([90, 0, 0])
        difference() {
            translate([0, 0, -0.1]) cylinder(h = 0.2, r = 0.7);
            translate([0, 0, -0.2]) cylinder(h = 0.4, r = 0.5);
            translate([-1, -1, -1]) cube([1, 2, 2]);
        }
}
