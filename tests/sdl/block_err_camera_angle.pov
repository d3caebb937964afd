camera { location -z*5 angle 180 }
