// The background rgb is premultiplied by (1 - transmit).
background { rgbt <1, 0.5, 0.25, 0.5> }
