// Placeholder so the skeleton builds; replaced by the module's first real source.
