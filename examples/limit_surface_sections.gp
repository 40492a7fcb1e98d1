# Sections of the limit surfaces written by `contensou-stick-without-creep <dir>`:
#   gnuplot -e "dir='<dir>'; out='docs/images'" examples/limit_surface_sections.gp
# Axes: force / (f N), torque / (f N R).
if (!exists("dir")) dir = 'out/limit_surface'
if (!exists("out")) out = 'docs/images'
set terminal pngcairo size 760,560 font ",11"
set size ratio -1
set grid
set key inside center center

set output out.'/limit_surface_meridian.png'
set title "Limit surface, section Fy = 0 (a meridian: unshifted profiles are axisymmetric)"
set xlabel "Fx / (f N)"
set ylabel "Mz / (f N R)"
plot dir.'/uniform_xz.dat' w l lw 2 lc rgb '#1f77b4' t 'uniform, exact', \
     dir.'/uniform_ellipsoid_xz.dat' w l lw 1.5 dt 2 lc rgb '#1f77b4' t 'uniform, ellipsoid', \
     dir.'/hertz_xz.dat' w l lw 2 lc rgb '#2ca02c' t 'Hertz, exact', \
     dir.'/hertz_ellipsoid_xz.dat' w l lw 1.5 dt 2 lc rgb '#2ca02c' t 'Hertz, ellipsoid', \
     dir.'/seed_xz.dat' w l lw 2 lc rgb '#d62728' t 'seed tire, exact', \
     dir.'/seed_ellipsoid_xz.dat' w l lw 1.5 dt 2 lc rgb '#d62728' t 'seed tire, ellipsoid'

set terminal pngcairo size 1400,520 font ",11"
set output out.'/limit_surface_seed_rolling.png'
set multiplot layout 1,3 title "Seed tire rolling (kx = 0.14) against the unshifted seed tire and the ellipsoid"
set key inside center center font ",9"
set title "Fy = 0"
set xlabel "Fx / (f N)"
set ylabel "Mz / (f N R)"
plot dir.'/seed_kx_xz.dat' w l lw 2 lc rgb '#d62728' t 'kx = 0.14', \
     dir.'/seed_xz.dat' w l lw 1.5 lc rgb '#7f7f7f' t 'kx = 0', \
     dir.'/seed_ellipsoid_xz.dat' w l lw 1.5 dt 2 lc rgb '#000000' t 'ellipsoid'
set title "Fx = 0"
set xlabel "Fy / (f N)"
plot dir.'/seed_kx_yz.dat' w l lw 2 lc rgb '#d62728' t 'kx = 0.14', \
     dir.'/seed_yz.dat' w l lw 1.5 lc rgb '#7f7f7f' t 'kx = 0', \
     dir.'/seed_ellipsoid_xz.dat' w l lw 1.5 dt 2 lc rgb '#000000' t 'ellipsoid'
set title "Mz = 0"
set xlabel "Fx / (f N)"
set ylabel "Fy / (f N)"
plot dir.'/seed_kx_xy.dat' w l lw 2 lc rgb '#d62728' t 'kx = 0.14', \
     dir.'/seed_xy.dat' w l lw 1.5 lc rgb '#7f7f7f' t 'kx = 0 and ellipsoid'
unset multiplot
