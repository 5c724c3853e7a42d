/* cpfg's movements: tropisms with an angle and an intensity, and a torque;
   elasticities past 1 (cpfg clamps the turn, not the elasticity) */
angle increment: 30
initial line width: 1
tropism: T: 0.3,-1,0 E: 3
tropism: T: 1,0,0 A: 90 E: 0.1 S: 0.05
tropism: T: 0,0,2 I: 0.5 A: 45 E: 0.8
torque: T: 0,0,1 E: 1.5
