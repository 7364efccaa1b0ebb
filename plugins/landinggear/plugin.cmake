# Plugin manifest: the plugins this one builds on (a selective build brings them in).
set(AIRSHAPE_PLUGIN_REQUIRES)
