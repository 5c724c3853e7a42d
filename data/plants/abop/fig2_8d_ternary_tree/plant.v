angle increment: 30
initial line width: 1
line width increment: 0
initial color: 1
color increment: 0
line style: cylinder
contour sides: 8
tropism direction: -0.61,0.77,-0.19
initial elasticity: 0.4
elasticity increment: 0.0
viewpoint: 0,0.2,1
view reference point: 0,0,0
twist: 0
projection: parallel
front distance: -10000.0
back distance: 10000.0
scale factor: 0.9
z buffer: on
