# The axisymmetric model (doc/axisymmetric.md): a 2D mesh in (r, z). Included at the end of tests/CMakeLists.txt,
# whose variables it uses (EXPECT_ERROR, INDENT, MUMPS_LU, PLASTIC_LAW, RUN_RESTART).
set(AXI_BLOCK ${CMAKE_SOURCE_DIR}/inputs/axisymmetric_block.geo)
set(AXI_MESHES)
# A unit block for the patch tests (triangles, and quadrilaterals), and a 100 um block for the elastic contact
# references, graded from 5 nm cells within 400 nm of the tip at 0.075 times the distance (a coarser far field,
# 0.3, made the loads 0.5% high).
set(AXI_UNIT "-setnumber width 1 -setnumber depth 1 -setnumber h_tip 0.1 -setnumber h_far 0.3 -setnumber r_fine 0.3")
set(AXI_WIDE "-setnumber width 100000 -setnumber depth 100000 -setnumber h_tip 5 -setnumber h_far 20000")
foreach(spec "patch_tri;${AXI_UNIT}" "patch_quad;${AXI_UNIT} -setnumber quads 1"
             "elastic_quad;${AXI_WIDE} -setnumber r_fine 400 -setnumber grow 0.075 -setnumber quads 1")
  list(GET spec 0 name)
  list(GET spec 1 params)
  separate_arguments(params)
  add_custom_command(OUTPUT ${MESHDIR}/axi_${name}.msh
    COMMAND ${GMSH_EXECUTABLE} -2 ${AXI_BLOCK} ${params} -format msh41 -o ${MESHDIR}/axi_${name}.msh > /dev/null
    DEPENDS ${AXI_BLOCK})
  list(APPEND AXI_MESHES ${MESHDIR}/axi_${name}.msh)
endforeach()
add_custom_command(OUTPUT ${MESHDIR}/kick_section.msh
  COMMAND ${GMSH_EXECUTABLE} -2 ${CMAKE_CURRENT_SOURCE_DIR}/meshes/kick_section.geo -setnumber L 6000 -setnumber Lc 400
    -setnumber Nc 80 -setnumber No 16 -format msh41 -o ${MESHDIR}/kick_section.msh > /dev/null
  DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/meshes/kick_section.geo)
list(APPEND AXI_MESHES ${MESHDIR}/kick_section.msh)
add_custom_target(axisymmetric_meshes ALL DEPENDS ${AXI_MESHES})

set(TEST_LABEL validation)
# Flat-punch patch test on the section: a uniaxial stress state with hoop strain nu eps (u_r = nu eps r) is
# exact in P1, P2, Q1 and Q2; every node's reaction over its ring's tributary area is -E d / H to 1e-8 (a P2
# corner on the axis has a ring of zero area, and must carry no force).
set(AXI_PUNCH -domain_young 100 -domain_poisson 0.3 -formulation small -bc_roller bottom:z -indenter_type flat
  -indenter_radius 10 -load_depth 0.01 -load_steps 2 -load_unload 0 -expect_patch -contact_uzawa_rtol 1e-10
  -contact_penetration_rtol 1e-10 -snes_rtol 1e-13 -output_fields 0 -quiet ${MUMPS_LU})
foreach(spec "P1;tri;1" "P2;tri;2" "Q1;quad;1" "Q2;quad;2")
  list(GET spec 0 el)
  list(GET spec 1 mesh)
  list(GET spec 2 deg)
  indent_mpi_test(NAME axisymmetric_patch_${el}_np2 NP 2 LABELS validation
    COMMAND $<TARGET_FILE:test_contact> -mesh_file ${MESHDIR}/axi_patch_${mesh}.msh -mesh_perturb 0.3
    -disc_degree ${deg} ${AXI_PUNCH} -output_dir ${CMAKE_CURRENT_BINARY_DIR}/axi_patch_${el} -output_overwrite)
endforeach()
# The rigid sphere (R 1000 nm, to h/R = 0.1) against its exact solution (Segedin 1957; Hertz's paraboloid is
# 0.1 h/R above it), and Sneddon's cone, each within 0.5% (measured: +0.17 to +0.33%, +0.15 to +0.35%).
set(AXI_ELASTIC -mesh_file ${MESHDIR}/axi_elastic_quad.msh -domain_young 100 -domain_poisson 0.3 -bc_fixed bottom
  -contact_gap reference -formulation small -load_unload 0 -load_depth 100 -load_steps 5 -expect_tol 0.005 -quiet)
indent_mpi_test(NAME axisymmetric_sphere_Q1_np2 NP 2 LABELS validation
  COMMAND $<TARGET_FILE:test_contact> ${AXI_ELASTIC} -indenter_type sphere -indenter_radius 1000 -expect_sphere
  -output_dir ${CMAKE_CURRENT_BINARY_DIR}/axi_sphere -output_overwrite)
indent_mpi_test(NAME axisymmetric_sneddon_Q1_np2 NP 2 LABELS validation
  COMMAND $<TARGET_FILE:test_contact> ${AXI_ELASTIC} -indenter_type cone -expect_sneddon
  -output_dir ${CMAKE_CURRENT_BINARY_DIR}/axi_sneddon -output_overwrite)
# Oliver-Pharr's epsilon and beta by the indenter's shape (cone 0.72 and 1, punch 1 and 1) recover the reduced
# modulus of Sneddon's load of the same elastic run: the punch to 1e-8, the cone to 1% (tests/check_op_shapes.py).
foreach(np 1 2)
  indent_script_test(op_shapes_section_np${np} ${INDENT_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_op_shapes.py
    --mpiexec ${MPIEXEC_EXECUTABLE} --indent $<TARGET_FILE:indent> --workdir ${CMAKE_CURRENT_BINARY_DIR}/op_shapes${np}
    --np ${np} -- -mesh_file ${MESHDIR}/axi_elastic_quad.msh -domain_young 100 -domain_poisson 0.3 -bc_fixed bottom
    -contact_gap reference -contact_friction 0 -formulation small -load_depth 100 -load_steps 5 -load_unload_steps 20
    -load_unload_growth 1 -op_fraction 1 -op_poisson 0.3 -output_fields 0 -quiet)
  set_tests_properties(op_shapes_section_np${np} PROPERTIES PROCESSORS ${np})
endforeach()

# Newton on a plastic section pulled to 2% (small strain) and 20% (finite strain) in 4 steps: the Jacobian with
# its hoop terms (u_r / r in the strain, the hoop stress against N_a / r, at finite strain also in the geometric
# stiffness) equals central differences of the residual (measured: 2e-9 to 3e-9 relative), and Newton converges
# quadratically. At finite strain the order estimates are 1.64 to 2.01 (Q1) and 1.68 (P1), the low ones where
# the last iterates near round-off: 1.6 is asked there, still far from an inconsistent tangent's 1.
set(AXI_NEWTON -mesh_perturb 0.2 ${PLASTIC_LAW} -bc_fixed bottom -load_predictor none -output_fields 0 -snes_rtol 1e-14
  -snes_atol 1e-13 -quiet -newton_steps 4,0 ${MUMPS_LU})
set(TEST_LABEL component)
foreach(spec "small_Q1;quad;1;small;0.02;1.8" "small_P2;tri;2;small;0.02;1.8" "finite_Q1;quad;1;finite;0.2;1.6"
             "finite_P1;tri;1;finite;0.2;1.6")
  list(GET spec 0 name)
  list(GET spec 1 mesh)
  list(GET spec 2 deg)
  list(GET spec 3 form)
  list(GET spec 4 tension)
  list(GET spec 5 order)
  indent_mpi_test(NAME axisymmetric_newton_${name}_np2 NP 2 LABELS component
    COMMAND $<TARGET_FILE:test_plastic_newton> -mesh_file ${MESHDIR}/axi_patch_${mesh}.msh -disc_degree ${deg}
    -formulation ${form} -newton_tension ${tension} -newton_order ${order} ${AXI_NEWTON})
endforeach()

# Kick's law on the section at finite strain against Dao et al.'s 25.8 GPa (70.3 deg cone, friction 0.15, E 70,
# nu 0.3, yield 0.3), on a core of 5 nm cells 400 nm wide, 2.5 nm steps to 60 nm: P / h^2 within 1% of its mean
# once the contact spans 25 cells, the mean within 2% of Dao's (measured: 25.44 GPa, -1.4%, spread -0.8 to
# +1.0%; 25.43 with a 600 nm core). With 10 nm cells or 5 nm steps it oscillated by 2.5 to 4.6%
# (doc/axisymmetric.md).
set(TEST_LABEL validation)
indent_script_test(axisymmetric_kick_dao_np2 ${INDENT_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_kick.py --section
  --indent $<TARGET_FILE:indent> --mesh ${MESHDIR}/kick_section.msh --workdir ${CMAKE_CURRENT_BINARY_DIR}/axi_kick
  --np 2 --mpiexec ${MPIEXEC_EXECUTABLE} --mpiexec-args= --young 70 --yield 0.3 --friction 0.15
  --options "-formulation finite"
  --depth 60 --steps 24 --min-elements 25 --tol 0.01 --expect-C 25.8 --C-tol 0.02)
set_tests_properties(axisymmetric_kick_dao_np2 PROPERTIES PROCESSORS 2 TIMEOUT 600)

# inputs/cone_axisymmetric.opts runs (coarse, shallow, as the example_* tests); its fields are a section of
# triangles that check_xdmf.py, meshio and ParaView read (every field of every step equal to indent.h5; 77 when
# a reader is missing), and scripts/plot-indent.py draws its curve, imprint profile and (r, z) slice.
set(TEST_LABEL input)
set(AXI_EXAMPLE_DIR ${CMAKE_CURRENT_BINARY_DIR}/example_cone_axisymmetric)
indent_mpi_test(NAME example_cone_axisymmetric_np2 NP 2 LABELS input
  COMMAND $<TARGET_FILE:indent> -options_file ${CMAKE_SOURCE_DIR}/inputs/cone_axisymmetric.opts
  -mesh_file ${CMAKE_SOURCE_DIR}/inputs/axisymmetric_film.geo -mesh_geo_parameters h_tip=20,h_far=400,r_fine=200
  -load_depth 20 -load_steps 4 -load_unload_steps 20 -output_fields_every 1 -output_dir ${AXI_EXAMPLE_DIR}
  -output_overwrite -quiet)
set_tests_properties(example_cone_axisymmetric_np2 PROPERTIES FIXTURES_SETUP axi_example)
indent_script_test(axisymmetric_xdmf_index ${INDENT_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_xdmf.py
  ${AXI_EXAMPLE_DIR}/indent.xdmf)
foreach(reader meshio paraview)
  indent_script_test(axisymmetric_xdmf_${reader} ${INDENT_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_xdmf_${reader}.py
    ${AXI_EXAMPLE_DIR}/indent.xdmf)
  set_tests_properties(axisymmetric_xdmf_${reader} PROPERTIES SKIP_RETURN_CODE 77)
endforeach()
indent_script_test(axisymmetric_plots ${INDENT_PYTHON} ${CMAKE_SOURCE_DIR}/scripts/plot-indent.py ${AXI_EXAMPLE_DIR}
  --out ${CMAKE_CURRENT_BINARY_DIR}/axisymmetric_plots)
# The example's fields revolved into 3D (scripts/revolve.py): the solid's volume is N sin(d) times the section's
# integral of r dA with every wedge positively oriented, the fields are the section's turned (measured: 0 to 3e-16),
# meshio reads the XDMF, a 3D run is refused.
indent_script_test(axisymmetric_revolve ${INDENT_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_revolve.py ${AXI_EXAMPLE_DIR}
  ${CMAKE_CURRENT_BINARY_DIR}/axisymmetric_revolve)
set_tests_properties(axisymmetric_xdmf_index axisymmetric_xdmf_meshio axisymmetric_xdmf_paraview axisymmetric_plots
  axisymmetric_revolve PROPERTIES FIXTURES_REQUIRED axi_example)
# A section's mesh turned into a 3D one (scripts/revolve-mesh.py): 3, 2 or 1 tetrahedra a triangle and segment,
# conforming, positive, their volume sin(d) / d times the ring's (measured: equal to the 12 digits printed), the
# boundary exactly the named surfaces, every node on a meridian of a section node; bad sections refused in one line.
indent_script_test(axisymmetric_revolve_mesh ${INDENT_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_revolve_mesh.py
  --workdir ${CMAKE_CURRENT_BINARY_DIR}/axi_revolve_mesh)
# A 3D model on the section where its indenter allows it (scripts/sectionmodel.py), the default of the inverse fit
# and the sweep helper: the options converted (a cone, a sphere on the multilayer) or kept 3D with the reason (a
# Berkovich, a scratch, off the axis, a mesh of its own), the converted model run, indent-fit's and sweep.py's --3d.
indent_script_test(axisymmetric_section_model ${INDENT_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_section_model.py
  --indent $<TARGET_FILE:indent> --workdir ${CMAKE_CURRENT_BINARY_DIR}/axi_section_model)
# The section and the 3D model on that section's mesh revolved (12 segments of a quarter): inputs/fit-cone.opts's
# case (a 70.3 degree cone with a 20 nm tip radius into a power-law film, friction 0.15, finite strain) to 20 nm
# in 1.25 nm steps, on a coarse graded mesh (2.5 nm cells at the tip). The same nodes in (r, z), the same load path,
# no step cut: measured 2.95% and 2.36% at 1.25 and 2.5 nm (two rings in contact), at most 0.90% from 5 nm; on
# cells of 1.25 nm to 60 nm (doc/axisymmetric.md) at most 0.81% at every depth.
set(TEST_LABEL validation)
indent_script_test(axisymmetric_vs_revolved_3d_np2 ${INDENT_PYTHON}
  ${CMAKE_CURRENT_SOURCE_DIR}/check_revolved_vs_section.py --indent $<TARGET_FILE:indent>
  --mesh ${CMAKE_SOURCE_DIR}/inputs/axisymmetric_film.geo
  --geo-parameters h_tip=2.5,h_far=400,r_fine=10,grow=0.1 --workdir ${CMAKE_CURRENT_BINARY_DIR}/axi_vs_revolved
  --np 2 --mpiexec ${MPIEXEC_EXECUTABLE} --mpiexec-args= --segments 12 --tol 0.01 --from 5 --tol-all 0.035
  --options "-film_model plastic -film_hardening power -film_young 70 -film_poisson 0.3 -film_yield 0.3
  -film_hardening_exponent 0.2 -substrate_model plastic -substrate_hardening power -substrate_young 70
  -substrate_poisson 0.3 -substrate_yield 0.3 -substrate_hardening_exponent 0.2 -bc_fixed bottom -indenter_type cone
  -indenter_radius 20 -contact_friction 0.15 -load_depth 20 -load_steps 16 -load_unload 0 -output_fields 0 -quiet")
set_tests_properties(axisymmetric_vs_revolved_3d_np2 PROPERTIES PROCESSORS 2 TIMEOUT 300)
set(TEST_LABEL input)
# scripts/export-curves.py on the section: the NIGET and Hysitron curves as for 3D runs, and the imprint revolved:
# imprint.gsf the top profile at each pixel's radius (measured: 4e-7 nm of 14.5, float32), imprint.xyz its pixels.
set(TEST_LABEL regression)
indent_script_test(export_curves_section ${INDENT_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_export_curves.py
  ${AXI_EXAMPLE_DIR} --workdir ${CMAKE_CURRENT_BINARY_DIR}/export_curves/section)
set_tests_properties(export_curves_section PROPERTIES FIXTURES_REQUIRED axi_example)

# A section stopped after 3 steps on 2 ranks and continued on 1 gives the uninterrupted run's curve, summary and
# fields (measured: 1e-14 of their largest values); other model options or another mesh are refused.
set(TEST_LABEL production)
indent_script_test(restart_axisymmetric_np2_to_1 ${RUN_RESTART} --workdir ${CMAKE_CURRENT_BINARY_DIR}/restart_axi
  --np 2,1 --stop 3 --rtol 1e-10 --changed-option=-film_yield=0.35
  --mesh-change=-mesh_geo_parameters=h_tip=50,h_far=400,r_fine=200
  -- -options_file ${CMAKE_SOURCE_DIR}/inputs/cone_axisymmetric.opts
  -mesh_file ${CMAKE_SOURCE_DIR}/inputs/axisymmetric_film.geo
  -mesh_geo_parameters h_tip=40,h_far=400,r_fine=200 -load_depth 20 -load_steps 5 -load_unload_steps 10 -quiet
  -film_yield 0.3)
set_tests_properties(restart_axisymmetric_np2_to_1 PROPERTIES PROCESSORS 2)
# The densifying glass (its history holds a plastic strain with a trace) stopped and continued the same way: the
# curve and every field, the compaction among them, as uninterrupted (measured: 1e-15); a changed yield pressure
# is refused.
indent_script_test(restart_densifying_np2_to_1 ${RUN_RESTART} --workdir ${CMAKE_CURRENT_BINARY_DIR}/restart_densifying
  --np 2,1 --stop 3 --rtol 1e-10 --changed-option=-domain_yield_pressure=9
  --mesh-change=-mesh_geo_parameters=width=2000,depth=2000,h_tip=25,h_far=200,r_fine=200
  -- -mesh_file ${CMAKE_SOURCE_DIR}/inputs/axisymmetric_block.geo
  -mesh_geo_parameters width=2000,depth=2000,h_tip=20,h_far=200,r_fine=200 -domain_young 70 -domain_poisson 0.17
  -domain_model densifying -domain_yield 6 -domain_yield_pressure 8 -domain_densification_modulus 20 -bc_fixed bottom
  -indenter_type cone -indenter_radius 10 -contact_friction 0.1 -load_depth 20 -load_steps 5 -load_unload_steps 10
  -quiet)
set_tests_properties(restart_densifying_np2_to_1 PROPERTIES PROCESSORS 2)

# Bad input: what a section cannot represent is refused in one line that names the way out.
set(TEST_LABEL "input;faults")
set(AXI_OK -mesh_file ${MESHDIR}/axi_patch_quad.msh -domain_young 100 -domain_poisson 0.3 -bc_fixed bottom
  -load_depth 0.01 -output_fields 0 -quiet)
indent_script_test(bad_axisymmetric_pyramid ${EXPECT_ERROR}
  "-indenter_type berkovich is a pyramid, which the axisymmetric model .a 2D mesh. cannot represent.+the cone of \
the same projected area is -indenter_type cone -indenter_angle 70.3"
  ${INDENT} ${AXI_OK} -indenter_type berkovich)
indent_script_test(bad_axisymmetric_cube_corner ${EXPECT_ERROR} "-indenter_type cone -indenter_angle 42.28"
  ${INDENT} ${AXI_OK} -indenter_type cube_corner)
indent_script_test(bad_axisymmetric_off_axis ${EXPECT_ERROR} "-indenter_axis 0.1,0.*on the axisymmetric model"
  ${INDENT} ${AXI_OK} -indenter_type cone -indenter_axis 0.1,0)
indent_script_test(bad_axisymmetric_scratch ${EXPECT_ERROR} "-scratch_length: a scratch slides the indenter off the axis"
  ${INDENT} ${AXI_OK} -indenter_type cone -scratch_length 0.1)
indent_script_test(bad_axisymmetric_symmetry_factor ${EXPECT_ERROR} "-contact_symmetry_factor does not apply to the axisymmetric"
  ${INDENT} ${AXI_OK} -indenter_type cone -contact_symmetry_factor 2)
set(TEST_LABEL validation)

# Load steps that follow the mesh (doc/load-steps.md): with -load_edge_steps 4 the contact's edge moves at most a
# quarter of the surface's node spacing per loading step (4 uniform steps moved it 2.8 spacings), the steps rise to
# exactly the largest depth, and they are the same on 1 and 2 ranks; on a section and on the coarse 3D paper case.
set(TEST_LABEL parallel)
set(RUN_EDGE_STEPS ${INDENT_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_edge_steps.py --mpiexec ${MPIEXEC_EXECUTABLE}
  --indent $<TARGET_FILE:indent>)
indent_script_test(edge_steps_section_np2 ${RUN_EDGE_STEPS} --workdir ${CMAKE_CURRENT_BINARY_DIR}/edge_steps_section
  -- -mesh_file ${AXI_BLOCK} -mesh_geo_parameters width=1000,depth=1000,h_tip=5,h_far=200,r_fine=100 ${PLASTIC_LAW}
  -formulation small -bc_fixed bottom -indenter_type cone -indenter_radius 20 -load_depth 20 -load_steps 4
  -load_unload 0 -output_fields 0 -quiet)
set_tests_properties(edge_steps_section_np2 PROPERTIES PROCESSORS 2)
indent_script_test(edge_steps_paper_np2 ${RUN_EDGE_STEPS} --workdir ${CMAKE_CURRENT_BINARY_DIR}/edge_steps_paper
  --edge-steps 2 -- ${PAPER_COARSE_OPTS} -load_unload 0 -output_fields 0)
set_tests_properties(edge_steps_paper_np2 PROPERTIES PROCESSORS 2)

# Multilayer sections (inputs/axisymmetric_multilayer.geo). One layer of the paper's film on silicon is
# axisymmetric_film.geo's section: gmsh makes the same mesh, so the curves agree to the solver tolerance; the
# coating-on-interlayer stack under the cone gives the same curve on 1 and 2 ranks.
set(TEST_LABEL validation)
set(AXI_ML_CASE -bc_fixed bottom -indenter_type cone -indenter_radius 50 -contact_friction 0.1 -load_depth 30
  -load_steps 6 -load_unload_steps 20 -contact_uzawa_rtol 1e-9 -snes_rtol 1e-10 -output_fields 0 -quiet)
set(AXI_FILM_GEO "-mesh_file ${CMAKE_SOURCE_DIR}/inputs/axisymmetric_film.geo -mesh_geo_parameters")
set(AXI_ML_GEO "-mesh_file ${CMAKE_SOURCE_DIR}/inputs/axisymmetric_multilayer.geo -mesh_geo_parameters")
indent_script_test(axisymmetric_multilayer_vs_film ${RUN_CURVES_INDENT} --workdir ${ML_DIR}/axi_same_mesh --np 2
  --rtol 1e-9
  --variant "film:${AXI_FILM_GEO} film=300,h_tip=20,h_far=400 ${ML_AL_film_S} ${ML_SI_S}"
  --variant "stack:${AXI_ML_GEO} n_layers=1,t1=300,h_tip=20,h_far=400 ${ML_AL_layer1_S} ${ML_SI_S}"
  -- ${AXI_ML_CASE})
set(TEST_LABEL parallel)
indent_script_test(axisymmetric_multilayer_np12 ${RUN_CURVES_INDENT} --workdir ${ML_DIR}/axi_np12 --np 1,2 --rtol 1e-8
  -- -options_file ${CMAKE_SOURCE_DIR}/inputs/multilayer_axisymmetric.opts
  -mesh_file ${CMAKE_SOURCE_DIR}/inputs/axisymmetric_multilayer.geo
  -mesh_geo_parameters n_layers=2,t1=100,t2=200,h_tip=20,h_far=400 -load_depth 20 -load_steps 4 -load_unload_steps 20
  -contact_uzawa_rtol 1e-10 -snes_rtol 1e-12 -output_fields 0 -quiet)
set_tests_properties(axisymmetric_multilayer_vs_film axisymmetric_multilayer_np12 PROPERTIES PROCESSORS 2)

# An indenter given as a table of its height against the radius (-indenter_type table): the 70.3 degree cone with
# a 50 nm tip radius as 100 chords on the tip and one along the mantle gives the analytic cone's curve on a section
# (measured: 1.1e-6 of P_max apart), and so does the same table as a spreadsheet in a European locale saves it (a
# byte-order mark, semicolons, decimal commas, CRLF); bad tables are refused in one line naming the file.
set(TEST_LABEL validation)
set(AXI_TABLE ${CMAKE_CURRENT_SOURCE_DIR}/data/indenter_cone70_R50.csv)
set(AXI_TABLE_SHEET ${CMAKE_CURRENT_SOURCE_DIR}/data/indenter_cone70_R50_spreadsheet.csv)
indent_script_test(axisymmetric_table_vs_cone ${RUN_CURVES_INDENT} --workdir ${CMAKE_CURRENT_BINARY_DIR}/axi_table
  --np 2 --rtol 1e-5 --atol 1e-4
  --variant "cone:-indenter_type cone"
  --variant "table:-indenter_type table -indenter_profile ${AXI_TABLE}"
  --variant "spreadsheet:-indenter_type table -indenter_profile ${AXI_TABLE_SHEET}"
  -- -options_file ${CMAKE_SOURCE_DIR}/inputs/cone_axisymmetric.opts
  -mesh_file ${CMAKE_SOURCE_DIR}/inputs/axisymmetric_film.geo
  -mesh_geo_parameters h_tip=5,h_far=400,r_fine=100 -load_depth 20 -load_steps 8 -load_edge_steps 0
  -load_unload_steps 20 -output_fields 0 -quiet)
set_tests_properties(axisymmetric_table_vs_cone PROPERTIES PROCESSORS 2)
set(TEST_LABEL "input;faults")
file(WRITE ${BAD_DIR}/table_text.csv "r,h\n0,0\n10,abc\n")
file(WRITE ${BAD_DIR}/table_one.csv "0,0\n")
file(WRITE ${BAD_DIR}/table_falling.csv "0,0\n10,5\n20,4\n")
file(WRITE ${BAD_DIR}/table_offset.csv "1,0\n10,5\n")
foreach(spec "text;line 3: not a pair of numbers" "one;1 point.s.; a profile needs at least 2"
             "falling;line 3: the height must not fall away from the tip"
             "offset;line 1: the first point must be the tip")
  list(GET spec 0 name)
  list(GET spec 1 why)
  indent_script_test(bad_table_${name} ${EXPECT_ERROR} "-indenter_profile '.*table_${name}.csv'.*${why}"
    ${INDENT} ${AXI_OK} -indenter_type table -indenter_profile ${BAD_DIR}/table_${name}.csv)
endforeach()
indent_script_test(bad_table_missing ${EXPECT_ERROR} "-indenter_profile '.*no_such.csv': cannot open the file"
  ${INDENT} ${AXI_OK} -indenter_type table -indenter_profile ${BAD_DIR}/no_such.csv)
indent_script_test(bad_table_without_profile ${EXPECT_ERROR} "-indenter_type table needs -indenter_profile FILE"
  ${INDENT} ${AXI_OK} -indenter_type table)

# Load control on a section: the film under the cone reaches -load_force 10 uN (each step its share, to 1e-6),
# unloads to zero force, and continues after a restart on the same curve.
set(TEST_LABEL parallel)
indent_script_test(axisymmetric_load_control_np2 ${RUN_LOAD_CONTROL}
  --workdir ${CMAKE_CURRENT_BINARY_DIR}/axi_load_control
  --force 10 --limit 30 --rtol 1e-6 --restart-after 2 --unload-to-zero --newton-ratio 2
  -- -options_file ${CMAKE_SOURCE_DIR}/inputs/cone_axisymmetric.opts
  -mesh_file ${CMAKE_SOURCE_DIR}/inputs/axisymmetric_film.geo
  -mesh_geo_parameters h_tip=20,h_far=400,r_fine=200 -load_steps 4 -load_unload_steps 20 -output_fields 0 -quiet)
set_tests_properties(axisymmetric_load_control_np2 PROPERTIES PROCESSORS 2)
# A table indenter's checkpoint keeps its points: a restart with the file unchanged continues, with one height
# changed it is refused in one line.
set(TEST_LABEL production)
indent_script_test(restart_table_indenter ${CMAKE_CURRENT_SOURCE_DIR}/check_table_restart.sh $<TARGET_FILE:indent>
  ${AXI_TABLE} ${CMAKE_CURRENT_BINARY_DIR}/restart_table
  -- -options_file ${CMAKE_SOURCE_DIR}/inputs/cone_axisymmetric.opts
  -mesh_file ${CMAKE_SOURCE_DIR}/inputs/axisymmetric_film.geo -mesh_geo_parameters h_tip=20,h_far=400,r_fine=200
  -load_depth 20 -load_steps 4 -load_unload_steps 20 -output_fields 0)

# The section's direct solve factors the free rows alone (src/solvers/heldlu.c): J x = b to 1e-10 on the first
# set-up, after a free row that was only on its diagonal couples again (PCREDISTRIBUTE, which keeps the rows it
# found first, is printed beside it) and after a condition more changed the held rows; the free block is the
# dofs less the held ones.
add_executable(test_held_lu test_held_lu.c)
target_link_libraries(test_held_lu PRIVATE indentcore)
target_include_directories(test_held_lu PRIVATE ${CMAKE_SOURCE_DIR}/src/solvers)
foreach(np 1 2)
  indent_mpi_test(NAME unit_held_lu_np${np} NP ${np} LABELS unit COMMAND $<TARGET_FILE:test_held_lu>
    -options_file ${CMAKE_SOURCE_DIR}/inputs/fit-sphere.opts -mesh_file ${CMAKE_SOURCE_DIR}/inputs/axisymmetric_film.geo
    -mesh_geo_parameters h_tip=40,h_far=400,r_fine=200
    -output_fields 0 -quiet -output_dir ${CMAKE_CURRENT_BINARY_DIR}/held_lu_np${np} -output_overwrite)
endforeach()

# The fit's model files (inputs/fit-*.opts, section and 3D) each start a run: mesh, options, two steps on 2 ranks.
indent_script_test(inputs_fit_models_start_np2 ${CMAKE_CURRENT_SOURCE_DIR}/check_inputs_start.sh ${MPIEXEC_EXECUTABLE}
  $<TARGET_FILE:indent> ${CMAKE_CURRENT_BINARY_DIR}/inputs_start ${CMAKE_SOURCE_DIR}/inputs/fit-cone.opts
  ${CMAKE_SOURCE_DIR}/inputs/fit-sphere.opts ${CMAKE_SOURCE_DIR}/inputs/fit-fused-silica.opts
  ${CMAKE_SOURCE_DIR}/inputs/fit-fused-silica-densifying.opts ${CMAKE_SOURCE_DIR}/inputs/fit-fused-silica-cone.opts)
set_tests_properties(inputs_fit_models_start_np2 PROPERTIES PROCESSORS 2 WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
