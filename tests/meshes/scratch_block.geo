// A half block (y >= 0, mirror plane y = 0) of hexahedra for scratch tests with a sphere that indents at
// the origin and slides along +x: a uniformly fine core [x0, x1] x [0, Wc] x [-Wc, 0] of cells of edge e
// holds the track and the contact beside and under it, so that every position of the indenter sees the
// same discretisation (a mesh graded from one point would make the lateral force change with x only
// because the cells do). Outside the core, No cells per direction grow by a geometric progression whose
// first cell is as large as a core cell, out to a block [x0 - L, x1 + L] x [0, Wc + L] x [-(Wc + L), 0]
// that is large against the contact, so its finite size matters little.
// L = 2000 is 14 contact radii of the tests' spheres. L = 5000 gave 5% less load (the Cattaneo-Mindlin
// sphere) and took the scratch tests twice as long: GAMG needs more iterations on the longer, flatter
// outer cells.
// -setnumber e <nm> -setnumber x0 <nm> -setnumber x1 <nm> -setnumber Wc <nm> -setnumber L <nm>
// -setnumber No <cells>; (x1 - x0) / e and Wc / e must be whole numbers of cells.
DefineConstant[ e = 25, x0 = -250, x1 = 450, Wc = 250, L = 2000, No = 5 ];
Nx = Round((x1 - x0) / e);
Nw = Round(Wc / e);
If (Nx < 1 || Fabs(Nx * e - (x1 - x0)) > 1e-6 * e || Nw < 1 || Fabs(Nw * e - Wc) > 1e-6 * e)
  Error("scratch_block.geo: x1 - x0 (%g nm) and Wc (%g nm) must be positive multiples of e (%g nm)", x1 - x0, Wc, e);
  Abort;
EndIf
If (No < 1 || No != Round(No) || L <= e)
  Error("scratch_block.geo: No must be a whole number >= 1 (got %g) and L > e (got L = %g nm, e = %g nm)", No, L, e);
  Abort;
EndIf
// the ratio r of the outer progression: e (r^No - 1) / (r - 1) = L, by fixed-point iteration (a
// contraction near the root when L is much larger than e No; otherwise r tends to 1, a uniform extension)
r = 2;
For k In {1:100}
  r = (1 + L * (r - 1) / e)^(1 / No);
EndFor
ones[] = {};
cum[] = {};  // layer tops of the outer progression, as fractions of L
For k In {1:No}
  ones[] += {1};
  cum[] += {e * (r^k - 1) / (r - 1) / L};
EndFor
Point(1) = {x0 - L, 0, 0}; Point(2) = {x0, 0, 0}; Point(3) = {x1, 0, 0}; Point(4) = {x1 + L, 0, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};
// the left extension runs towards the core, so its cells shrink by 1/r to end with a cell of size e
Transfinite Curve{1} = No + 1 Using Progression 1 / r;
Transfinite Curve{2} = Nx + 1;
Transfinite Curve{3} = No + 1 Using Progression r;
// along y, then down in z: each extrusion returns, per source entity, its top, then the new entity
a[] = Extrude {0, Wc, 0} { Curve{1, 2, 3}; Layers{Nw}; Recombine; };
b[] = Extrude {0, L, 0} { Curve{a[0], a[4], a[8]}; Layers{ones[], cum[]}; Recombine; };
c[] = Extrude {0, 0, -Wc} { Surface{a[1], a[5], a[9], b[1], b[5], b[9]}; Layers{Nw}; Recombine; };
d[] = Extrude {0, 0, -L} { Surface{c[0], c[6], c[12], c[18], c[24], c[30]}; Layers{ones[], cum[]}; Recombine; };
xl = x0 - L; xr = x1 + L; yb = Wc + L; zb = -(Wc + L);
tol = 1e-6 * L;
Physical Volume("domain") = Volume In BoundingBox{xl - tol, -tol, zb - tol, xr + tol, yb + tol, tol};
Physical Surface("top") = Surface In BoundingBox{xl - tol, -tol, -tol, xr + tol, yb + tol, tol};
Physical Surface("bottom") = Surface In BoundingBox{xl - tol, -tol, zb - tol, xr + tol, yb + tol, zb + tol};
Physical Surface("front") = Surface In BoundingBox{xl - tol, -tol, zb - tol, xr + tol, tol, tol};
Physical Surface("back") = Surface In BoundingBox{xl - tol, yb - tol, zb - tol, xr + tol, yb + tol, tol};
Physical Surface("left") = Surface In BoundingBox{xl - tol, -tol, zb - tol, xl + tol, yb + tol, tol};
Physical Surface("right") = Surface In BoundingBox{xr - tol, -tol, zb - tol, xr + tol, yb + tol, tol};
