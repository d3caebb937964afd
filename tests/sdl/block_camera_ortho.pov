camera { orthographic location <0, 0, -10> look_at <0, 0, 0> }
