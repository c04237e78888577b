// The object box's refit in TRACK, one image axis at a time, from the two
// frame differences around the object (paper eq. 2-4 applied to extents):
// Dif(t-2,t-1) spans object(t-2) and object(t-1), Dif(t-1,t) spans
// object(t-1) and object(t). Their common part is object(t-1)
// (`previous`); Dif(t-1,t)'s extent (`both`) reaches past it on the side
// the object moved to, by the motion, and that far edge is object(t)'s
// leading edge, measured in the current frame.
//
// follow_axis places object(t) there: the SAD pattern of paper eq. 5 finds
// where the object's texture went, which on a spinning ball is not where the
// ball went (measured 6-16 px off on a 61-99 px ball at 5 rev/s), and the
// silhouette is not one frame late as object(t-1) is.
//
// pull_axis is the refit used when the differences do not give object(t)
// (too little motion, or an extent the object's size cannot explain): the
// SAD box's size moves towards object(t-1)'s and its centre is pulled
// towards it, a bounded step per frame.
#pragma once

namespace dsp {

// One axis of a box: pixels [start, start + size).
struct span {
    int start = 0;
    int size = 0;
    int end() const { return start + size; }
};

// object(t-1) on one axis from the extents of Dif(t-2,t-1) (`before`) and
// Dif(t-1,t) (`after`): their common part, or, when they share one edge
// only, `size` from that edge. A shared edge is the motion reversing within
// the three frames (the bounce of a thrown ball: object(t-2) and object(t)
// both above object(t-1)); the common part then also holds the nearer of
// object(t-2) and object(t), and only the shared edge is object(t-1)'s.
// Edges within 1 px count as shared.
span previous_axis(span before, span after, int size);

// object(t-1) on one axis where the motion reversed and brought object(t)
// back to object(t-2): both extents, Dif(t-2,t-1)'s (`before`) and
// Dif(t-1,t)'s (`after`), share both edges (within 1 px) and are larger
// than the last box `last` by over an eighth of it (at least 2 px, the
// tolerance), so their common part is all three. object(t-1) is the last
// box's size from the end the last box holds (within the tolerance; not
// when it holds both or neither), when Dif(t-3,t-2)'s extent `earlier`
// stops short of that end by the motion (within the tolerance): the object
// came to it in the pair before. True and `previous` set then. A 30 px
// ball thrown over teddy bounced so, its extents both 54 px high: the
// common part was not the ball's size, no box was followed, and the box
// reported at the bounce was 41 x 43 px for the 35 px ball (the SAD box
// pulled towards that part). The pair before is asked for by a 160 px
// ball thrown slowly, near its apex: both extents held it whole (169 px)
// around a last box 145 px high that held their end, but the extent
// before them held that end too.
bool returned_axis(span earlier, span before, span after, span last, span* previous);

// object(t) on one axis, `size` wide, from object(t-1)'s extent `previous`,
// Dif(t-1,t)'s extent `both` and the last box `last`. The object moved
// towards the side where `both` reaches further past `previous`, by
// |both| - size (the motion along the axis). With no side further, object(t)
// is centred in `both`. Where `both` is narrower than the object, the last
// box moved only as far as it must to hold `both`: such a difference holds
// the parts that changed, not the rim (on a slow ball, 140 px spinning
// 1 rev/s about z at 1 px per frame, Dif(t-1,t) was 110-120 px high, its
// bottom within 3 px of the ball's and its top 17-27 px short; centred in it
// the box stood 8 px low).
span follow_axis(span previous, span both, span last, int size);

// object(t) on one axis, `placed` (the silhouette's), held at Dif(t-1,t)'s
// extent `both` where it stands past that extent's end by more than 2 px
// and the SAD box `found` of the same size has its side within 2 px of
// that end: the rim was read there, by the differences and by the texture
// alike. A leading rim the differences missed leaves the extent short,
// which is why a fast object's box may stand past it (dsp/extent_window.h);
// the SAD box then stands past it too, on the ball. Fitted to the last
// pairs' extents, a small ball whose motion turns or slows was placed 6-9
// px past an extent whose end the SAD box shared (a 22 px ball circling at
// 25 px a pair, its step down 20 -> 17 -> 11 px: 7.2 and 8.9 px off).
span held_at_extent_end(span placed, span found, span both);

// The axis across the motion: Dif(t-1,t) reached past object(t-1) by
// `moved` px on it and by `moved_other` on the other axis, at least min_shift
// and four times as far. There the rim runs along the motion and the
// differences miss it where its contrast is low, so object(t-1)'s size
// measured on that axis is not taken below the last box's (a 155 px ball
// thrown spinning over teddy, 13 px a frame down and 0.4 px across after its
// bounce: both differences missed its left 10 px, the box shrank to 145 px
// and stood 6.4 px off).
bool across_motion(int moved, int moved_other);

// Dif(t-1,t)'s extent `both` under half the last box `last` on an axis: a
// part of the object, not its outline (a slow ball whose other parts change
// too little: at 1 px per frame a 130 px ball spinning about x over "cones"
// gave Dif(t-1,t) 43 px wide at its leading edge, and the box centred on it
// was 44 px ahead of the ball).
bool is_part(span both, span last);

// object(t) on that axis, as large as the last box, from the part's outer
// edge: the end when the part lies past the last box's centre (it leads
// towards the end), else the start.
span part_axis(span both, span last);

// The SAD box `found` gets a size moved towards `mask`'s (object(t-1)) by at
// most a step, and its centre moved by half the offset between the last box
// and the mask (object(t-1) was seen where the last box was), at most a
// step; then it is kept inside [0, limit). step = max(1, larger of the two
// sizes / 8): with the box's size alone, a box started small on an object
// cut by the image border needed ~20 frames to grow to the object.
span pull_axis(span found, span last, span mask, int min_size, int max_size, int limit);

// The SAD box `found` at a size held (`size`), about its centre, moved to
// the nearest place that leaves least of `mask` (object(t-1)) outside it,
// at most a step (as pull_axis's); then kept inside [0, limit). A mask
// shorter than the box is a slow ball's thin differences, which miss a rim:
// its centre is not the object's (pulled towards it, the box of a 52 px
// ball whose top 12 px the differences missed went 6 px down in two pairs).
span hold_axis(span found, span mask, int size, int limit);

// object(t) on one axis from `both`, the extent of Dif(key, t), which spans
// object(key) and object(t) (dsp/key_frame.h), and the object's displacement
// `shift` since the key: `both` less |shift| on the side away from the motion.
span keyed_axis(span both, int shift);

// The displacement since the key on one axis read from Dif(key, t)'s
// extent `both` and the key's object box `key`: the object moved towards the
// side where `both` reaches past the key's box, by that much, when on the
// other side it reaches no further (within 2 px: the key's box may be a
// little narrower than the outline); 0 when it reaches equally far on both
// sides, within 2 px. False otherwise (the key's box did not outline the
// object). For a pattern that turned with its texture: an 80 px ball at
// 1 px per frame spinning 0.5 rev/s about y kept its key's pattern still for
// 8 pairs while Dif(key, t) grew by 1 px each.
bool difference_shift(span both, span key, int* shift);

// How far `both` reaches past the key's box on its further side.
int key_reach(span both, span key);

// Dif(key, t)'s extent `both` holds the key's box `key` on this axis, within
// 2 px (the key's box may be that much wider than the outline): the whole
// outline, not a part of it (as at a key's first pair, where Dif(key, t) is
// Dif(t-1,t)).
bool holds_key_box(span both, span key);

// A key's pattern the difference contradicts: where Dif(key, t)'s extent
// `both` holds the key's box `key` (within 2 px) and reads a displacement
// (difference_shift) of at most `most` px that differs from the pattern's
// `shift` by more than key_frame::max_step, `shift` becomes the difference's.
// A texture that turns against its ball can still match within the turned
// rule: a 125 px ball at 2 px per frame spinning 0.5 rev/s about y, its
// key's pattern read -1, -3, -4 px in its first pairs while Dif(key, t)
// reached 2, 4, 7 px past the key's box on the side it went, none on the
// other.
bool contradicted_shift(span both, span key, int most, int* shift);

// The displacement on an axis the key's box did not outline, read against
// `first`, Dif(key, t)'s extent at the key's first pair: that spans
// object(key) and the next object, so its trailing end stays while the
// leading end moves with the object (difference_shift with `first` for the
// key's box; the first pair's own motion, at most max_step px, is not in
// it). True and `shift` set when that reads at most `most` px while
// `usable`; false when the extent reached past `first` on both sides or
// further than the object could have moved (`first` was a part: `usable`
// cleared, for the key's life). Traced: a
// 140 px ball circling upwards at 1 px per frame, spinning 0.6 rev/s about
// x, its key's box 4 px low; the pattern read the texture 1-3 px down while
// Dif(key, t)'s top went from y 162 to 156 over 8 pairs, its bottom at 305.
bool first_extent_shift(span both, span first, int most, bool* usable, int* shift);

// The displacement since the key `shift` on one axis, at most Dif(key, t)'s
// extent `both` less the key's box `key` in size, + 1 px: that extent holds
// object(key) and object(t), so it is larger than the object by the motion.
// A pattern that follows a turning texture reads more (a 140 px ball moving
// 1 px a pair along x, spinning 0.5 rev/s about x: 7-8 px down for a ball
// that had not moved in y, its Dif(key, t) 2 px higher than the key's box).
// `bounded` is set when `shift` was more and `both` is at least the key's box
// less 2 px (the whole outline; the key's box may be 2 px wide of it): the
// caller then takes that axis from `both`. A shorter extent is a part (a
// key's first pair, Dif(key, t) = Dif(t-1, t): 116 px high for a 140 px
// ball, whose box shrank to it, 9.6 px off).
int bounded_shift(span both, span key, int shift, bool* bounded);

// object(t) on one axis for a key whose pattern does not follow its object
// (a texture that outruns it: a 140 px ball at 1 px per frame spinning
// 1 rev/s about y had its SAD pattern found 7 px a pair off a silhouette that
// moved 1), from Dif(key, t)'s extent `both` and the key's box `key`: their
// hull holds object(key) and object(t) whatever the texture did. Across the
// motion (`across`) the object is the hull (it moved little there; at most
// a quarter more than the key's box, + 1): a silhouette of three frames
// misses a slow ball's poles there (120-131 px of 140 measured), Dif(key, t)
// over a texture turned for a few pairs does not. Along it, `size` wide at
// the end the hull reaches further past the key's box (the object moved
// there), centred in the hull when neither does; at least the key's box plus
// twice the hull's reach past its trailing side, for a hull past the key's box
// on both sides says that box was short by that much on each (a 160 px ball
// spinning 2 rev/s about y was keyed short along the motion).
// Across the motion the object may drift too (a ball circling): where
// Dif(key, t) grew further at one end than at the other since its first
// reading `first`, and the silhouette's centre moved that way since the key
// (`toward`: +1 towards the end, -1 the start, 0 not min_shift px), the
// hull less that growth at its trailing end (not under the key's box). The
// hull alone held where a 73 px ball circling at 3 px a pair was at the
// key: it drifted 1 px a pair across, and its box grew to 87 px, 7 px off
// centre. Either reading alone misleads: a key's box short at one end moves
// the silhouette's centre (a 120 px ball keyed 109 px wide), and a texture
// turning into one pole first grows Dif(key, t) there (a 185 px ball
// spinning 3 rev/s, its box 4-6 px short).
span outline_key_axis(span both, span key, int size, bool across, span first, int toward);

// A size moved towards `target` by at most max(1, larger of the two / 8),
// within [min_size, max_size] and at most `limit`.
int step_size(int size, int target, int min_size, int max_size, int limit);

}  // namespace dsp
