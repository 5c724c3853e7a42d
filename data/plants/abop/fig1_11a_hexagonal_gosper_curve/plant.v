angle increment: 60
initial line width: 2 pixels
line width increment: 0
initial color: 1
color increment: 0
viewpoint: 0,0,1
view reference point: 0,0,0
twist: 0
projection: parallel
front distance: -10000.0
back distance: 10000.0
scale factor: 0.9
z buffer: on
