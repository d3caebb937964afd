cylinder { <0, 0, 0>, <0, 2, 0>, 0.5 }
cylinder { 0, x, 0.25 open }
cone { <0, 0, 0>, 1, <0, 3, 0>, 0 }
cone { 0, 1, y, 0.5 open translate x*3 }
