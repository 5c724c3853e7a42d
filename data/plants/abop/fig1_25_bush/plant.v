angle increment: 22.5
initial line width: 1.2
line width increment: 0.15
initial color: 1
color increment: 1
line style: cylinder
contour sides: 8
viewpoint: 0,0.3,1
view reference point: 0,0,0
twist: 0
projection: parallel
front distance: -10000.0
back distance: 10000.0
scale factor: 0.9
z buffer: on
