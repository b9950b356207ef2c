// The axisymmetric section of tests/meshes/kick_block.geo: r in [0, L], z in [-L, 0] (drawn as gmsh's x = r,
// y = z) of quadrilaterals, a uniformly fine core [0, Lc] x [-Lc, 0] of Nc cells per edge under the tip and
// a geometric progression of No cells outside it whose first is as large as a core cell. For Kick's law, whose
// P / h^2 is flat only while every ring of nodes entering the contact is as wide as the last.
// -setnumber L <nm> -setnumber Lc <nm> -setnumber Nc <cells> -setnumber No <cells>
DefineConstant[ L = 2000, Lc = 100, Nc = 10, No = 7 ];
e = Lc / Nc;
r = 2; // e (r^No - 1) / (r - 1) = L - Lc, by fixed-point iteration
For k In {1:100}
  r = (1 + (L - Lc) * (r - 1) / e)^(1 / No);
EndFor
Point(1) = {0, 0, 0};   Point(2) = {Lc, 0, 0};   Point(3) = {L, 0, 0};
Point(4) = {0, -Lc, 0}; Point(5) = {Lc, -Lc, 0}; Point(6) = {L, -Lc, 0};
Point(7) = {0, -L, 0};  Point(8) = {Lc, -L, 0};  Point(9) = {L, -L, 0};
// core edges, then the outer ones oriented away from the core so that each progression starts fine
Line(1) = {1, 2}; Line(2) = {4, 5}; Line(3) = {1, 4}; Line(4) = {2, 5};
Line(5) = {2, 3}; Line(6) = {5, 6}; Line(7) = {3, 6};
Line(8) = {4, 7}; Line(9) = {5, 8}; Line(10) = {7, 8};
Line(11) = {8, 9}; Line(12) = {6, 9};
Curve Loop(1) = {1, 4, -2, -3};   Plane Surface(1) = {1};  // core
Curve Loop(2) = {5, 7, -6, -4};   Plane Surface(2) = {2};  // beside it
Curve Loop(3) = {2, 9, -10, -8};  Plane Surface(3) = {3};  // below it
Curve Loop(4) = {6, 12, -11, -9}; Plane Surface(4) = {4};  // the far corner
Transfinite Curve{1:4} = Nc + 1;
Transfinite Curve{7, 10} = Nc + 1;
Transfinite Curve{5, 6, 8, 9} = No + 1 Using Progression r;
Transfinite Curve{11, 12} = No + 1 Using Progression r;
Transfinite Surface{1:4};
Recombine Surface{1:4};
Physical Surface("domain") = {1:4};
Physical Curve("top") = {1, 5};
Physical Curve("bottom") = {10, 11};
Physical Curve("axis") = {3, 8};
Physical Curve("side") = {7, 12};
