// The sky: a zenith-to-horizon gradient, a sun disk with a soft glow, and the ground's colour
// below the horizon. The forward pass uses the same function for specular sky reflections, so
// reflections and background agree.
vec3 sky_radiance(vec3 direction, ViewConstants v) {
    vec3 d = normalize(direction);
    float elevation = d.y;
    vec3 sun = v.sun_direction.xyz;
    float cos_sun = max(dot(d, sun), 0.0);
    if (elevation < 0.0) {
        // Below the horizon: the lit ground, darkening towards the nadir, blended over a narrow
        // band so the horizon is not a hard line.
        vec3 ground = v.ground_albedo.rgb * (0.35 + 0.65 * max(sun.y, 0.0)) * v.sun_radiance.rgb * 0.35;
        float band = smoothstep(0.0, -0.03, elevation);
        return mix(v.sky_horizon.rgb, ground, band);
    }
    float t = pow(1.0 - elevation, 4.0);
    vec3 sky = mix(v.sky_zenith.rgb, v.sky_horizon.rgb, t);
    float glow = pow(cos_sun, 64.0) * 0.6 + pow(cos_sun, 8.0) * 0.15;
    float disk = smoothstep(0.99990, 0.99996, cos_sun) * 40.0;
    return sky + v.sun_radiance.rgb * (glow + disk);
}
