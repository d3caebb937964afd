// Transforms are applied after the other fix-ups, whatever their position.
camera { translate x location <0, 0, -5> direction z*2 rotate y*90 }
