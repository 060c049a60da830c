// Lambertian diffuse BRDF: f_d = diffuseColor / π. Source: Lambert 1760; Filament §4.5 keeps
// Lambert over Burley on mobile (the visual difference is small, Burley costs a pow5 and more).
// fp16: a constant, exact enough in mediump (see math.glsl on PI).
float diffuse_lambert() {
    return INV_PI;
}
