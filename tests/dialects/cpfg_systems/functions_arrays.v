angle increment: 25
initial line width: 1
function: growth.func 50
function: bend.func
function: growth.func
