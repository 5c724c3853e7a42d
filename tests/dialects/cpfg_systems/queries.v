angle increment: 30
initial line width: 1
line width increment: 0.5
initial color: 1
color increment: 1
