#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/fxaa_layouts.h"

// FXAA, the quality variant (Lottes 2009, "FXAA" whitepaper, and its 3.x
// quality algorithm): a pixel on an edge is blended with its neighbour across
// the edge by how much of the pixel the edge, searched along its length, is
// taken to cover. One output pixel per invocation, from gl_FragCoord.
//
// The source is the sRGB frame read through a UNORM view, and the output is
// written through one (engine/vk/fxaa_pass.h): every value here is
// gamma-encoded, as the algorithm expects its input ("Luma Conversion": luma
// from non-linear colour), the blend mixes encoded values, and nothing is
// decoded or encoded on the way.
//
// Every read is a texel fetch. The whitepaper reads the pair of pixels either
// side of the edge with one bilinear tap between them; on a CPU rasteriser
// (lavapipe) two fetches cost less than one filtered tap.
layout(set = 0, binding = FXAA_BINDING_SOURCE) uniform sampler2D source;

layout(location = 0) out vec4 outColor;

// Tuning, the whitepaper's high-quality values ("Tuning"): a pixel is left as
// it is when the contrast of its cross of neighbours is below kEdgeThreshold
// of the brightest of them, or below kEdgeThresholdMin at all (dark areas,
// where noise would otherwise be smoothed). kSubpixel caps the sub-pixel
// blend: 1 would soften texture detail, 0 leaves single-pixel features.
const float kEdgeThreshold = 0.166;
const float kEdgeThresholdMin = 0.0833;
const float kSubpixel = 0.75;
// The end-of-edge search: pixels advanced per step, each way. Short steps
// first, where most edges end, then longer ones; an edge is followed at most
// 18 pixels each way and blended as if it ended there.
const int kSearchSteps = 6;
const int kSearchStep[kSearchSteps] = int[](1, 1, 2, 2, 4, 8);
// The search stops where the luma along the edge has moved this fraction of
// the step across it away from the edge's own average ("End-of-edge Search").
const float kEndOfEdge = 0.25;

// Perceptual luma: the Rec. 709 weights over gamma-encoded R'G'B'. The
// thresholds above are contrasts of it; in linear luminance a dark edge would
// fall below them.
float lumaOf(vec3 encodedRgb) {
    return dot(encodedRgb, vec3(0.2126, 0.7152, 0.0722));
}

// A pixel of the source, the nearest inside it for one beyond its edge.
vec4 texelAt(ivec2 pixel, ivec2 size) {
    return texelFetch(source, clamp(pixel, ivec2(0), size - 1), 0);
}

float lumaAt(ivec2 pixel, ivec2 size) {
    return lumaOf(texelAt(pixel, size).rgb);
}

void main() {
    const ivec2 size = textureSize(source, 0);
    const ivec2 pixel = ivec2(gl_FragCoord.xy);
    const vec4 centre = texelFetch(source, pixel, 0);

    // "Local Contrast Check": the cross of four neighbours (y grows down the
    // image: north is the row above).
    // lavapipe runs every branch of a shader for all pixels of a block
    // unless all of them skip a loop, so every fetch costs everywhere: the
    // cross's colours are kept for the final blend, which mixes with one
    // of them.
    const vec4 north = texelAt(pixel + ivec2(0, -1), size);
    const vec4 south = texelAt(pixel + ivec2(0, 1), size);
    const vec4 west = texelAt(pixel + ivec2(-1, 0), size);
    const vec4 east = texelAt(pixel + ivec2(1, 0), size);
    const float lumaM = lumaOf(centre.rgb);
    const float lumaN = lumaOf(north.rgb);
    const float lumaS = lumaOf(south.rgb);
    const float lumaW = lumaOf(west.rgb);
    const float lumaE = lumaOf(east.rgb);
    const float lumaMax = max(lumaM, max(max(lumaN, lumaS), max(lumaW, lumaE)));
    const float lumaMin = min(lumaM, min(min(lumaN, lumaS), min(lumaW, lumaE)));
    const float range = lumaMax - lumaMin;
    if (range < max(kEdgeThresholdMin, lumaMax * kEdgeThreshold)) {
        outColor = centre;
        return;
    }
    const float lumaNW = lumaAt(pixel + ivec2(-1, -1), size);
    const float lumaNE = lumaAt(pixel + ivec2(1, -1), size);
    const float lumaSW = lumaAt(pixel + ivec2(-1, 1), size);
    const float lumaSE = lumaAt(pixel + ivec2(1, 1), size);

    // "Sub-pixel Aliasing Test": a pixel unlike the 3x3 low-pass around it,
    // relative to the local contrast, is a feature thinner than a pixel (a
    // twig, a leaf's tip); it is blended more the more it stands out.
    const float lowPass = (2.0 * (lumaN + lumaS + lumaW + lumaE) + lumaNW + lumaNE + lumaSW + lumaSE) / 12.0;
    const float standsOut = smoothstep(0.0, 1.0, clamp(abs(lowPass - lumaM) / range, 0.0, 1.0));
    const float subpixelOffset = standsOut * standsOut * kSubpixel;

    // "Vertical/Horizontal Edge Test": second differences down the three
    // columns (a horizontal edge) against those along the three rows, the
    // centre's counted twice.
    const float acrossRows = 2.0 * abs(lumaN + lumaS - 2.0 * lumaM) + abs(lumaNW + lumaSW - 2.0 * lumaW) +
                             abs(lumaNE + lumaSE - 2.0 * lumaE);
    const float acrossColumns = 2.0 * abs(lumaW + lumaE - 2.0 * lumaM) + abs(lumaNW + lumaNE - 2.0 * lumaN) +
                                abs(lumaSW + lumaSE - 2.0 * lumaS);
    const bool horizontal = acrossRows >= acrossColumns;

    // The edge lies between this pixel and its neighbour on the steeper side.
    const float lumaBefore = horizontal ? lumaN : lumaW;
    const float lumaAfter = horizontal ? lumaS : lumaE;
    const float stepBefore = abs(lumaBefore - lumaM);
    const float stepAfter = abs(lumaAfter - lumaM);
    const bool after = stepAfter >= stepBefore;
    const ivec2 across = (after ? 1 : -1) * (horizontal ? ivec2(0, 1) : ivec2(1, 0));
    const ivec2 along = horizontal ? ivec2(1, 0) : ivec2(0, 1);
    const float edgeAverage = 0.5 * (lumaM + (after ? lumaAfter : lumaBefore));
    const float endThreshold = kEndOfEdge * max(stepBefore, stepAfter);

    // "End-of-edge Search": both ways along the edge, the average luma of the
    // pair of pixels either side of it, until that average leaves the edge's.
    // The first step's pairs, one pixel each way, are in the 3x3 already.
    const float pairBack = horizontal ? lumaW + (after ? lumaSW : lumaNW) : lumaN + (after ? lumaNE : lumaNW);
    const float pairAhead = horizontal ? lumaE + (after ? lumaSE : lumaNE) : lumaS + (after ? lumaSE : lumaSW);
    int distanceBack = kSearchStep[0], distanceAhead = kSearchStep[0]; // pixels from this one
    float endBack = 0.5 * pairBack - edgeAverage;   // pair luma minus the edge's average there
    float endAhead = 0.5 * pairAhead - edgeAverage;
    bool doneBack = abs(endBack) >= endThreshold, doneAhead = abs(endAhead) >= endThreshold;
    for (int i = 1; i < kSearchSteps && !(doneBack && doneAhead); ++i) {
        if (!doneBack) {
            distanceBack += kSearchStep[i];
            const ivec2 p = pixel - distanceBack * along;
            endBack = 0.5 * (lumaAt(p, size) + lumaAt(p + across, size)) - edgeAverage;
            doneBack = abs(endBack) >= endThreshold;
        }
        if (!doneAhead) {
            distanceAhead += kSearchStep[i];
            const ivec2 p = pixel + distanceAhead * along;
            endAhead = 0.5 * (lumaAt(p, size) + lumaAt(p + across, size)) - edgeAverage;
            doneAhead = abs(endAhead) >= endThreshold;
        }
    }

    // "Blending": at the nearer end, either this pixel's line (row or column)
    // takes the far side's luma (the pair's luma moves away from this
    // pixel's): the edge crosses into this line beyond that end and passes
    // through this pixel, covering half of it at the end and none in the
    // middle of the span; or the far line takes this pixel's luma: the edge
    // leaves through the far line and covers nothing of this pixel.
    const bool backNearer = distanceBack < distanceAhead;
    const float nearest = float(min(distanceBack, distanceAhead));
    const float endLuma = backNearer ? endBack : endAhead;
    const bool centreDarker = lumaM < edgeAverage;
    const bool edgeCrossesThisLine = (endLuma < 0.0) != centreDarker;
    const float edgeOffset = edgeCrossesThisLine ? 0.5 - nearest / float(distanceBack + distanceAhead) : 0.0;

    // The pixel moved towards the edge's other side by the larger of the two
    // coverages: a mix with the neighbour across it.
    const vec4 acrossColor = horizontal ? (after ? south : north) : (after ? east : west);
    outColor = mix(centre, acrossColor, max(edgeOffset, subpixelOffset));
}
