/* Colour helpers: the sRGB transfer function and IEEE half conversion. */
#include "texel.h"

/* The 8-bit decode tables, one array (internal.h names its rows
 * ls_srgb_table and ls_unorm8_table): the fast path decodes an
 * RGBA8 texel's four channels with one gather from it, reading an sRGB
 * texel's alpha 256 entries on (fast_gl.c, texel_v4). A table, not a
 * lazily filled array, so there is no run-time init (and no race, the
 * trap in Mesa's softpipe).
 *
 * Row 0, ls_srgb_table[c] = EOTF(c / 255) rounded to float, where
 * EOTF(v) = v / 12.92 for v ≤ 0.04045, else ((v + 0.055) / 1.055)^2.4
 * (IEC 61966-2-1). Generated in double precision by:
 *   for i in range(256): v = i/255; print("%.9g" % (v/12.92 if v <= 0.04045
 *                                   else ((v+0.055)/1.055)**2.4))
 *
 * Row 1, ls_unorm8_table[c] = c / 255 correctly rounded (GL 4.6 eq.
 * 2.1), the UNORM8 decode and the linear alpha of SRGB8: a load instead
 * of a divide per texel (a multiply by the rounded reciprocal is off by an
 * ulp for some codes). The compiler folds each division at translation
 * time, in the same IEEE single arithmetic a run-time division uses
 * (tested). */
#define U8_1(c) ((float)(c) / 255.0f)
#define U8_4(c) U8_1(c), U8_1((c) + 1), U8_1((c) + 2), U8_1((c) + 3)
#define U8_16(c) U8_4(c), U8_4((c) + 4), U8_4((c) + 8), U8_4((c) + 12)
#define U8_64(c) U8_16(c), U8_16((c) + 16), U8_16((c) + 32), U8_16((c) + 48)
const float ls_u8_decode[2][256] = {
    {
        0.0f, 0.000303526984f, 0.000607053967f, 0.000910580951f, 0.00121410793f, 0.00151763492f,
        0.0018211619f, 0.00212468888f, 0.00242821587f, 0.00273174285f, 0.00303526984f, 0.00334653576f,
        0.00367650732f, 0.00402471702f, 0.00439144204f, 0.00477695348f, 0.0051815167f, 0.00560539162f,
        0.00604883302f, 0.00651209079f, 0.00699541019f, 0.00749903204f, 0.00802319299f, 0.00856812562f,
        0.0091340587f, 0.00972121732f, 0.010329823f, 0.010960094f, 0.0116122452f, 0.0122864884f,
        0.0129830323f, 0.013702083f, 0.0144438436f, 0.0152085144f, 0.0159962934f, 0.0168073758f,
        0.0176419545f, 0.0185002201f, 0.019382361f, 0.0202885631f, 0.0212190104f, 0.0221738848f,
        0.0231533662f, 0.0241576324f, 0.0251868596f, 0.0262412219f, 0.0273208916f, 0.0284260395f,
        0.0295568344f, 0.0307134437f, 0.0318960331f, 0.0331047666f, 0.0343398068f, 0.0356013149f,
        0.0368894504f, 0.0382043716f, 0.0395462353f, 0.0409151969f, 0.0423114106f, 0.0437350293f,
        0.0451862044f, 0.0466650863f, 0.0481718242f, 0.049706566f, 0.0512694584f, 0.052860647f,
        0.0544802764f, 0.05612849f, 0.0578054302f, 0.0595112382f, 0.0612460542f, 0.0630100177f,
        0.0648032667f, 0.0666259386f, 0.0684781698f, 0.0703600957f, 0.0722718507f, 0.0742135684f,
        0.0761853815f, 0.0781874218f, 0.0802198203f, 0.0822827071f, 0.0843762115f, 0.086500462f,
        0.0886555863f, 0.0908417112f, 0.0930589628f, 0.0953074666f, 0.0975873471f, 0.0998987282f,
        0.102241733f, 0.104616484f, 0.107023103f, 0.109461711f, 0.111932428f, 0.114435374f,
        0.116970668f, 0.119538428f, 0.122138772f, 0.124771818f, 0.12743768f, 0.130136477f,
        0.132868322f, 0.13563333f, 0.138431615f, 0.141263291f, 0.144128471f, 0.147027266f,
        0.14995979f, 0.152926152f, 0.155926464f, 0.158960835f, 0.162029376f, 0.165132195f,
        0.1682694f, 0.171441101f, 0.174647404f, 0.177888416f, 0.181164244f, 0.184474995f,
        0.187820772f, 0.191201683f, 0.19461783f, 0.19806932f, 0.201556254f, 0.205078736f,
        0.20863687f, 0.212230757f, 0.2158605f, 0.2195262f, 0.223227957f, 0.226965874f,
        0.230740049f, 0.234550582f, 0.238397574f, 0.242281122f, 0.246201327f, 0.250158285f,
        0.254152094f, 0.258182853f, 0.262250658f, 0.266355605f, 0.270497791f, 0.274677312f,
        0.278894263f, 0.28314874f, 0.287440838f, 0.29177065f, 0.296138271f, 0.300543794f,
        0.304987314f, 0.309468923f, 0.313988713f, 0.318546778f, 0.323143209f, 0.327778098f,
        0.332451536f, 0.337163615f, 0.341914425f, 0.346704056f, 0.3515326f, 0.356400144f,
        0.36130678f, 0.366252596f, 0.37123768f, 0.376262123f, 0.381326011f, 0.386429434f,
        0.391572478f, 0.396755231f, 0.40197778f, 0.407240212f, 0.412542613f, 0.417885071f,
        0.42326767f, 0.428690497f, 0.434153636f, 0.439657174f, 0.445201195f, 0.450785783f,
        0.456411023f, 0.462077f, 0.467783796f, 0.473531496f, 0.479320183f, 0.48514994f,
        0.49102085f, 0.496932995f, 0.502886458f, 0.508881321f, 0.514917665f, 0.520995573f,
        0.527115126f, 0.533276404f, 0.539479489f, 0.545724461f, 0.552011402f, 0.55834039f,
        0.564711506f, 0.571124829f, 0.57758044f, 0.584078418f, 0.590618841f, 0.597201788f,
        0.603827339f, 0.610495571f, 0.617206562f, 0.623960392f, 0.630757136f, 0.637596874f,
        0.644479682f, 0.651405637f, 0.658374817f, 0.665387298f, 0.672443157f, 0.67954247f,
        0.686685312f, 0.693871761f, 0.701101892f, 0.70837578f, 0.715693501f, 0.723055129f,
        0.73046074f, 0.737910409f, 0.74540421f, 0.752942217f, 0.760524505f, 0.768151147f,
        0.775822218f, 0.783537792f, 0.79129794f, 0.799102738f, 0.806952258f, 0.814846572f,
        0.822785754f, 0.830769877f, 0.838799012f, 0.846873232f, 0.854992608f, 0.863157213f,
        0.871367119f, 0.879622397f, 0.887923118f, 0.896269353f, 0.904661174f, 0.913098652f,
        0.921581856f, 0.930110858f, 0.938685728f, 0.947306537f, 0.955973353f, 0.964686248f,
        0.97344529f, 0.98225055f, 0.991102097f, 1.0f,
    },
    {U8_64(0), U8_64(64), U8_64(128), U8_64(192)},
};

/* sample_srgb8_threshold[k] = EOTF((k + ½)/255), k = 0 … 254: the linear
 * values half-way (in the encoded domain) between codes k and k + 1, each
 * the double nearest the exact value. Generated with Python's decimal
 * module (50 digits):
 *   for k in range(255): x = (Decimal(k) + Decimal("0.5")) / 255
 *       print(float(x / Decimal("12.92") if x <= Decimal("0.04045")
 *             else ((x + Decimal("0.055")) / Decimal("1.055")) ** Decimal("2.4")).hex())
 */
static const double sample_srgb8_threshold[255] = {
    0x1.3e45677c176f7p-13, 0x1.dd681b3a23272p-12, 0x1.8dd6c15b1d4b4p-11,
    0x1.167cba8c94818p-10, 0x1.660e146b9a5d5p-10, 0x1.b59f6e4aa0393p-10,
    0x1.02986414d30a8p-9, 0x1.2a61110455f87p-9, 0x1.5229bdf3d8e66p-9,
    0x1.79f26ae35bd45p-9, 0x1.a1e5a03a8a4b5p-9, 0x1.cbf734477e0e7p-9,
    0x1.f8680590912c1p-9, 0x1.13a0be3e98ad5p-8, 0x1.2c4665c6bc58bp-8,
    0x1.4629793a399b0p-8, 0x1.614e607554158p-8, 0x1.7db96ca0c99d9p-8,
    0x1.9b6ed95fb6dbap-8, 0x1.ba72cde4cb5cap-8, 0x1.dac95df183297p-8,
    0x1.fc768ac1bd733p-8, 0x1.0fbf21f2dc489p-7, 0x1.21f234061c55cp-7,
    0x1.34d662df32ddcp-7, 0x1.486d8e075e9d4p-7, 0x1.5cb98d9e2545fp-7,
    0x1.71bc32a59ad46p-7, 0x1.87774749cc7c5p-7, 0x1.9dec8f23ba5bfp-7,
    0x1.b51dc7783fa2ap-7, 0x1.cd0ca7733ec84p-7, 0x1.e5bae05f5ea99p-7,
    0x1.ff2a1dda9da46p-7, 0x1.0cae0303fc81dp-6, 0x1.1a291cdf30864p-6,
    0x1.28072a5a9656bp-6, 0x1.3648f6d71d8d4p-6, 0x1.44ef4b4ef6b8fp-6,
    0x1.53faee688f616p-6, 0x1.636ca4889ebeep-6, 0x1.73452fe3532a6p-6,
    0x1.8385508caeef9p-6, 0x1.942dc48821f75p-6, 0x1.a53f47d76ca86p-6,
    0x1.b6ba9488d7613p-6, 0x1.c8a062c4c9086p-6, 0x1.daf168dac664fp-6,
    0x1.edae5b4de330dp-6, 0x1.006bf67056983p-5, 0x1.0a3767504c7e3p-5,
    0x1.1439d7f87bcfap-5, 0x1.1e739f4abdd1cp-5, 0x1.28e5135e29deap-5,
    0x1.338e8983f0647p-5, 0x1.3e70564c063c2p-5, 0x1.498acd89a2d57p-5,
    0x1.54de4257938ccp-5, 0x1.606b071c66583p-5, 0x1.6c316d8e6dd5ep-5,
    0x1.7831c6b7a0a43p-5, 0x1.846c62f955ceap-5, 0x1.90e1920fdffcep-5,
    0x1.9d91a31608f91p-5, 0x1.aa7ce4886f087p-5, 0x1.b7a3a448c57bfp-5,
    0x1.c5062fa0f9c99p-5, 0x1.d2a4d3463e6bcp-5, 0x1.e07fdb5bfcb10p-5,
    0x1.ee979376ae979p-5, 0x1.fcec469ea1be6p-5, 0x1.05bf1fa95233fp-4,
    0x1.0d26e3c54ebeap-4, 0x1.14ad945d08395p-4, 0x1.1c5355e946f1ep-4,
    0x1.24184ca308d86p-4, 0x1.2bfc9c84a7aeep-4, 0x1.3400694af6b4bp-4,
    0x1.3c23d67658241p-4, 0x1.4467074bcad3fp-4, 0x1.4cca1ed5f04c9p-4,
    0x1.554d3fe60b982p-4, 0x1.5df08d14f9170p-4, 0x1.66b428c41f9a1p-4,
    0x1.6f98351e5b03cp-4, 0x1.789cd418e0ac2p-4, 0x1.81c227741dc30p-4,
    0x1.8b0850bc8fe6bp-4, 0x1.946f714b98253p-4, 0x1.9df7aa4848998p-4,
    0x1.a7a11ca82cd65p-4, 0x1.b16be9300d4b9p-4, 0x1.bb583074add2ep-4,
    0x1.c56612db878dfp-4, 0x1.cf95b09b7e3e6p-4, 0x1.d9e729bd913dep-4,
    0x1.e45a9e1d883c9p-4, 0x1.eef02d6a9be77p-4, 0x1.f9a7f7281a9a9p-4,
    0x1.02410d57049f5p-3, 0x1.07bf5b94e038ap-3, 0x1.0d4ef5cf430b2p-3,
    0x1.12efeb7311b79p-3, 0x1.18a24bd8bbe9dp-3, 0x1.1e6626448412fp-3,
    0x1.243b89e6c58e7p-3, 0x1.2a2285dc393e6p-3, 0x1.301b292e38aa4p-3,
    0x1.362582d2ffac4p-3, 0x1.3c41a1adecb7ap-3, 0x1.426f948fbfc29p-3,
    0x1.48af6a36d7de4p-3, 0x1.4f01314f6f85fp-3, 0x1.5564f873d7af6p-3,
    0x1.5bdace2cb1a51p-3, 0x1.6262c0f127b37p-3, 0x1.68fcdf2724b0dp-3,
    0x1.6fa937238a68fp-3, 0x1.7667d72a66f3dp-3, 0x1.7d38cd6f28fe9p-3,
    0x1.841c2814d30edp-3, 0x1.8b11f52e2dc70p-3, 0x1.921a42bdf9326p-3,
    0x1.99351eb71d1f9p-3, 0x1.a06296fcd88fbp-3, 0x1.a7a2b962f040bp-3,
    0x1.aef593addc582p-3, 0x1.b65b3392f5350p-3, 0x1.bdd3a6b89f6d8p-3,
    0x1.c55efab676fe3p-3, 0x1.ccfd3d1579b02p-3, 0x1.d4ae7b5030ba9p-3,
    0x1.dc72c2d2d9a5bp-3, 0x1.e44a20fb8e723p-3, 0x1.ec34a31a6d0b4p-3,
    0x1.f4325671be069p-3, 0x1.fc4348361ab75p-3, 0x1.0233c2c7494c1p-2,
    0x1.064f8dca68078p-2, 0x1.0a750baa9e48dp-2, 0x1.0ea442e792155p-2,
    0x1.12dd39fa6c332p-2, 0x1.171ff755e9545p-2, 0x1.1b6c81666af86p-2,
    0x1.1fc2de920806ap-2, 0x1.242315389d220p-2, 0x1.288d2bb3dcb8fp-2,
    0x1.2d0128575ed1dp-2, 0x1.317f1170b096cp-2, 0x1.3606ed4763a09p-2,
    0x1.3a98c21d1d03fp-2, 0x1.3f34962da4212p-2, 0x1.43da6faef137cp-2,
    0x1.488a54d13bc06p-2, 0x1.4d444bbf088cap-2, 0x1.52085a9d37af4p-2,
    0x1.56d6878b122d7p-2, 0x1.5baed8a2577aap-2, 0x1.609153f74abf5p-2,
    0x1.657dff98bfecfp-2, 0x1.6a74e190289f3p-2, 0x1.6f75ffe1a0cbcp-2,
    0x1.7481608bfb425p-2, 0x1.79970988cdfcap-2, 0x1.7eb700cc7e40cp-2,
    0x1.83e14c464c956p-2, 0x1.8915f1e0608a3p-2, 0x1.8e54f77fd4542p-2,
    0x1.939e6304c03f5p-2, 0x1.98f23a4a45f6cp-2, 0x1.9e5083269ba32p-2,
    0x1.a3b9436b16e15p-2, 0x1.a92c80e437919p-2, 0x1.aeaa4159b27f7p-2,
    0x1.b4328a8e7be4ap-2, 0x1.b9c56240d1c5ap-2, 0x1.bf62ce2a462a8p-2,
    0x1.c50ad3ffc933ap-2, 0x1.cabd7971b30b4p-2, 0x1.d07ac42bcdb47p-2,
    0x1.d642b9d55eb84p-2, 0x1.dc15601130b20p-2, 0x1.e1f2bc7d9cba5p-2,
    0x1.e7dad4b493b27p-2, 0x1.edcdae4ba7707p-2, 0x1.f3cb4ed413cbfp-2,
    0x1.f9d3bbdac78d2p-2, 0x1.ffe6fae86d3d6p-2, 0x1.030288c0b9edcp-1,
    0x1.061702930bb93p-1, 0x1.0930eda934ca2p-1, 0x1.0c504cbf2cdcap-1,
    0x1.0f75228edec22p-1, 0x1.129f71d02c75cp-1, 0x1.15cf3d38f323dp-1,
    0x1.1904877d0f24bp-1, 0x1.1c3f534e5fea4p-1, 0x1.1f7fa35ccbe1bp-1,
    0x1.22c57a564448bp-1, 0x1.2610dae6c8f65p-1, 0x1.2961c7b86c188p-1,
    0x1.2cb8437355e5bp-1, 0x1.301450bdc8432p-1, 0x1.3375f23c225fbp-1,
    0x1.36dd2a90e443cp-1, 0x1.3a49fc5cb2566p-1, 0x1.3dbc6a3e58d79p-1,
    0x1.413476d2cf4fep-1, 0x1.44b224b53bf61p-1, 0x1.4835767ef70a2p-1,
    0x1.4bbe6ec78e26bp-1, 0x1.4f4d1024c7882p-1, 0x1.52e15d2aa54a6p-1,
    0x1.567b586b689cdp-1, 0x1.5a1b047794ed4p-1, 0x1.5dc063ddf3090p-1,
    0x1.616b792b94357p-1, 0x1.651c46ebd53f4p-1, 0x1.68d2cfa861810p-1,
    0x1.6c8f15e935e0fp-1, 0x1.70511c34a3c66p-1, 0x1.7418e50f54067p-1,
    0x1.77e672fc49c8cp-1, 0x1.7bb9c87ce563dp-1, 0x1.7f92e810e7315p-1,
    0x1.8371d436725abp-1, 0x1.87568f6a0f9dcp-1, 0x1.8b411c26b0098p-1,
    0x1.8f317ce5afb3ep-1, 0x1.9327b41ed8674p-1, 0x1.9723c44864498p-1,
    0x1.9b25afd7007afp-1, 0x1.9f2d793dcfaeep-1, 0x1.a33b22ee6cbccp-1,
    0x1.a74eaf58ed2a5p-1, 0x1.ab6820ebe3af1p-1, 0x1.af877a1462b15p-1,
    0x1.b3acbd3dfebbep-1, 0x1.b7d7ecd2d0ee0p-1, 0x1.bc090b3b79644p-1,
    0x1.c0401adf219b8p-1, 0x1.c47d1e237ecd4p-1, 0x1.c8c0176cd4466p-1,
    0x1.cd09091df5b70p-1, 0x1.d157f598497d1p-1, 0x1.d5acdf3bcae8ap-1,
    0x1.da07c8670c7a5p-1, 0x1.de68b3773a1c6p-1, 0x1.e2cfa2c81b559p-1,
    0x1.e73c98b41576dp-1, 0x1.ebaf97942dc33p-1, 0x1.f028a1c00b929p-1,
    0x1.f4a7b98dfa6ebp-1, 0x1.f92ce152ec2b7p-1, 0x1.fdb81b627af90p-1,
};

unsigned char ls_srgb_encode8(float v)
{
    /* The code k with threshold[k − 1] ≤ v < threshold[k]: round(255·OETF(v))
     * to the nearest, ties up, found by bisection among constants instead of
     * through pow (whose last bit is the C library's): the same codes on
     * any machine. NaN and v < threshold[0] (negative included) give 0. */
    int lo = 0, hi = 255;
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        if ((double)v >= sample_srgb8_threshold[mid - 1])
            lo = mid;
        else
            hi = mid - 1;
    }
    return (unsigned char)lo;
}

float sample_srgb_to_linear(float v)
{
    if (!(v > 0.04045f)) return v / 12.92f; /* also passes NaN through */
    return (float)pow(((double)v + 0.055) / 1.055, 2.4);
}

float sample_linear_to_srgb(float v)
{
    if (!(v > 0.0031308f)) return v * 12.92f;
    return (float)(1.055 * pow((double)v, 1.0 / 2.4) - 0.055);
}

float sample_half_to_float(uint16_t h)
{
    uint32_t sign = (uint32_t)(h & 0x8000u) << 16;
    uint32_t exp = (h >> 10) & 0x1fu;
    uint32_t man = h & 0x3ffu;
    uint32_t bits;
    float f;
    if (exp == 0) {
        /* Zero or subnormal: value = man × 2^−24, exact in float. */
        f = (float)man * 5.9604644775390625e-8f;
        return sign ? -f : f;
    }
    if (exp == 31)
        bits = sign | 0x7f800000u | (man << 13); /* inf / NaN */
    else
        bits = sign | ((exp + 112u) << 23) | (man << 13);
    memcpy(&f, &bits, sizeof f);
    return f;
}

uint16_t sample_float_to_half(float f)
{
    uint32_t x, sign, exp, man;
    memcpy(&x, &f, sizeof x);
    sign = (x >> 16) & 0x8000u;
    exp = (x >> 23) & 0xffu;
    man = x & 0x7fffffu;
    if (exp == 255) /* inf or NaN (keep a quiet NaN) */
        return (uint16_t)(sign | 0x7c00u | (man ? 0x200u : 0u));
    {
        int e = (int)exp - 127 + 15;
        if (e >= 31) return (uint16_t)(sign | 0x7c00u); /* overflow → inf */
        if (e <= 0) {
            /* Subnormal half (or zero): shift the full mantissa down with
             * round-to-nearest-even. */
            uint32_t m, shift, half_val, rem, r;
            if (e < -10) return (uint16_t)sign;
            m = man | 0x800000u;
            shift = (uint32_t)(14 - e);
            r = m >> shift;
            rem = m & ((1u << shift) - 1u);
            half_val = 1u << (shift - 1u);
            if (rem > half_val || (rem == half_val && (r & 1u))) ++r;
            return (uint16_t)(sign | r);
        }
        {
            uint32_t r = ((uint32_t)e << 10) | (man >> 13);
            uint32_t rem = man & 0x1fffu;
            /* Rounding may carry into the exponent, which is still right
             * (up to inf). */
            if (rem > 0x1000u || (rem == 0x1000u && (r & 1u))) ++r;
            return (uint16_t)(sign | r);
        }
    }
}
