angle increment: 30
tropism direction: 1,0,0
initial elasticity: 0.2
