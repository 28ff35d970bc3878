#version 330 core
// Display of the accumulation buffer (app/viewer/display_pipeline.h). Each side's image texture
// holds the mean linear radiance in RGB and the pixel's sample count in A; its error texture holds
// the relative standard error of the mean luminance (R) and 1 where adaptive sampling has finished
// the pixel (G). The colour view is renderer/tonemap.cpp's applyTonemap + encodeSrgb (the tests
// compare the two within 1/255); the error and sample-count views go through
// app/viewer/false_colour.cpp's ramp, and the adaptive-mask view through its wash, mirrored here.

// One side's textures: the split view draws each side over its part of the viewport (scissor),
// so a fragment samples one image, not both (llvmpipe would fetch both for a branch on the side).
uniform sampler2D uImage;
uniform sampler2D uError;
uniform vec2 uViewportOrigin;   // window pixels
uniform vec2 uViewportSize;
// The view is a compile-time constant: display_pipeline.cpp builds one program per view, defining
// STRATA_VIEW after the #version line. With the view a uniform, llvmpipe's colour pass took twice
// as long, paying for the views it did not show.
const int kView = STRATA_VIEW;  // 0 colour, 1 relative error, 2 sample count, 3 adaptive mask
uniform int uTonemap;           // 0 clamp, 1 reinhard, 2 aces
uniform float uExposure;        // stops
uniform float uErrorScale;      // relative error shown at the top of the ramp
uniform float uSampleScale;     // sample count shown at the top of the ramp

out vec4 fragColour;

const vec3 kNoSamples = vec3(0.25);
const vec3 kDoneGreen = vec3(0.10, 0.85, 0.25);
const float kDoneWash = 0.65;
const int kRampStops = 5;
const vec3 kRamp[kRampStops] = vec3[](vec3(0.05, 0.05, 0.40), vec3(0.00, 0.45, 1.00),
                                      vec3(0.10, 0.80, 0.20), vec3(1.00, 0.90, 0.00),
                                      vec3(1.00, 0.10, 0.00));

vec3 falseColour(float t) {
    float x = clamp(t, 0.0, 1.0) * float(kRampStops - 1);
    int i = min(int(floor(x)), kRampStops - 2);
    return mix(kRamp[i], kRamp[i + 1], x - float(i));
}

vec3 applyTonemap(vec3 linear) {
    vec3 x = max(linear, vec3(0.0)) * exp2(uExposure);
    vec3 mapped = x;
    if (uTonemap == 1) {
        mapped = x / (vec3(1.0) + x);
    } else if (uTonemap == 2) {
        // Narkowicz's fit of the ACES filmic curve.
        mapped = (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14);
    }
    return clamp(mapped, vec3(0.0), vec3(1.0));
}

// The sRGB curve's power segment 1.055 c^(1/2.4) - 0.055 as a fitted sum of c^(1/2), c^(1/4),
// c^(1/8) and c: within 0.25/255 of it on [0.0031308, 1] (checked on 2e5 points), cheaper than
// pow on llvmpipe, where pow is a log2 and an exp2 per channel (the colour pass: 12 -> 9 ms).
vec3 encodeSrgb(vec3 c) {
    c = clamp(c, vec3(0.0), vec3(1.0));
    vec3 root2 = sqrt(c);
    vec3 root4 = sqrt(root2);
    vec3 root8 = sqrt(root4);
    vec3 power = 0.662002687 * root2 + 0.684122060 * root4 - 0.323583601 * root8 - 0.0225411470 * c;
    return mix(power, 12.92 * c, lessThanEqual(c, vec3(0.0031308)));
}

void main() {
    vec2 uv = (gl_FragCoord.xy - uViewportOrigin) / uViewportSize;
    uv.y = 1.0 - uv.y;  // the images' first row is the top one
    vec4 pixel = texture(uImage, uv);
    vec3 colour;
    if (kView == 0) {
        colour = encodeSrgb(applyTonemap(pixel.rgb));
    } else if (kView == 3) {
        colour = encodeSrgb(applyTonemap(pixel.rgb));
        if (texture(uError, uv).g > 0.5) colour = mix(colour, kDoneGreen, kDoneWash);
    } else if (pixel.a <= 0.0) {
        colour = kNoSamples;
    } else if (kView == 1) {
        colour = falseColour(texture(uError, uv).r / uErrorScale);
    } else {
        colour = falseColour(pixel.a / uSampleScale);
    }
    fragColour = vec4(colour, 1.0);
}
