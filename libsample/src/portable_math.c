/*
 * The table behind sample_log2 (portable_math.h): for c_i = 1 + (i + ½)/128,
 * i = 0 … 127, {log2 c_i, 1/c_i}, each the double nearest the exact value.
 * Constants, not computed at start-up, so that no libm is involved.
 * Generated with Python's decimal module (correctly rounded ln, 50 digits):
 *
 *   from decimal import Decimal, getcontext
 *   getcontext().prec = 50
 *   ln2 = Decimal(2).ln()
 *   for i in range(128):
 *       c = 1 + (Decimal(i) + Decimal("0.5")) / 128
 *       print(float(c.ln() / ln2).hex(), float(1 / c).hex())
 */
#include "base.h"

const double ls_log2_table[128][2] = {
    {0x1.709c46d7aac77p-8, 0x1.fe01fe01fe020p-1}, {0x1.1363117a97b0cp-6, 0x1.fa11caa01fa12p-1},
    {0x1.c9363ba850f86p-6, 0x1.f6310aca0dbb5p-1}, {0x1.3ed3094685a26p-5, 0x1.f25f644230ab5p-1},
    {0x1.985bfc3495194p-5, 0x1.ee9c7f8458e02p-1}, {0x1.f1389833253a0p-5, 0x1.eae807aba01ebp-1},
    {0x1.24b5b7e135a3dp-4, 0x1.e741aa59750e4p-1}, {0x1.507b836033bb7p-4, 0x1.e3a9179dc1a73p-1},
    {0x1.7beee96b8a281p-4, 0x1.e01e01e01e01ep-1}, {0x1.a7111df348494p-4, 0x1.dca01dca01dcap-1},
    {0x1.d1e34e35b82dap-4, 0x1.d92f2231e7f8ap-1}, {0x1.fc66a0f0b00a5p-4, 0x1.d5cac807572b2p-1},
    {0x1.134e1b489062ep-3, 0x1.d272ca3fc5b1ap-1}, {0x1.284294b07a640p-3, 0x1.cf26e5c44bfc6p-1},
    {0x1.3d1146d9a8a64p-3, 0x1.cbe6d9601cbe7p-1}, {0x1.51bab907a5c8ap-3, 0x1.c8b265afb8a42p-1},
    {0x1.663f6fac91316p-3, 0x1.c5894d10d4986p-1}, {0x1.7a9fec7d05ddfp-3, 0x1.c26b5392ea01cp-1},
    {0x1.8edcae8352b6cp-3, 0x1.bf583ee868d8bp-1}, {0x1.a2f632320b86bp-3, 0x1.bc4fd65883e7bp-1},
    {0x1.b6ecf175f95e9p-3, 0x1.b951e2b18ff23p-1}, {0x1.cac163c770dc9p-3, 0x1.b65e2e3beee05p-1},
    {0x1.de73fe3b1480fp-3, 0x1.b37484ad806cep-1}, {0x1.f205339208f27p-3, 0x1.b094b31d922a4p-1},
    {0x1.02baba24d0664p-2, 0x1.adbe87f94905ep-1}, {0x1.0c62975542a8fp-2, 0x1.aaf1d2f87ebfdp-1},
    {0x1.15fa676bb08ffp-2, 0x1.a82e65130e159p-1}, {0x1.1f825f6d88e13p-2, 0x1.a574107688a4ap-1},
    {0x1.28fab35b32683p-2, 0x1.a2c2a87c51ca0p-1}, {0x1.32639636b2836p-2, 0x1.a01a01a01a01ap-1},
    {0x1.3bbd3a0a1dcfbp-2, 0x1.9d79f176b682dp-1}, {0x1.4507cfedd4fc4p-2, 0x1.9ae24ea5510dap-1},
    {0x1.4e43880e8fb6ap-2, 0x1.9852f0d8ec0ffp-1}, {0x1.577091b3378cbp-2, 0x1.95cbb0be377aep-1},
    {0x1.608f1b42948aep-2, 0x1.934c67f9b2ce6p-1}, {0x1.699f5248cd4b8p-2, 0x1.90d4f120190d5p-1},
    {0x1.72a1637cbc183p-2, 0x1.8e6527af1373fp-1}, {0x1.7b957ac51aac4p-2, 0x1.8bfce8062ff3ap-1},
    {0x1.847bc33d8618ep-2, 0x1.899c0f601899cp-1}, {0x1.8d54673b5c372p-2, 0x1.87427bcc092b9p-1},
    {0x1.961f90527409cp-2, 0x1.84f00c2780614p-1}, {0x1.9edd6759b25e0p-2, 0x1.82a4a0182a4a0p-1},
    {0x1.a78e146f7bef4p-2, 0x1.8060180601806p-1}, {0x1.b031befe06434p-2, 0x1.7e225515a4f1dp-1},
    {0x1.b8c88dbf8867ap-2, 0x1.7beb3922e017cp-1}, {0x1.c152a6c24cae6p-2, 0x1.79baa6bb6398bp-1},
    {0x1.c9d02f6ca47b4p-2, 0x1.77908119ac60dp-1}, {0x1.d2414c80bf27dp-2, 0x1.756cac201756dp-1},
    {0x1.daa6222064fb9p-2, 0x1.734f0c541fe8dp-1}, {0x1.e2fed3d097298p-2, 0x1.713786d9c7c09p-1},
    {0x1.eb4b847d15bcep-2, 0x1.6f26016f26017p-1}, {0x1.f38c567bcc541p-2, 0x1.6d1a62681c861p-1},
    {0x1.fbc16b902680ap-2, 0x1.6b1490aa31a3dp-1}, {0x1.01f57277264e0p-1, 0x1.691473a88d0c0p-1},
    {0x1.0604719f24eb2p-1, 0x1.6719f3601671ap-1}, {0x1.0a0dc34f8e1fcp-1, 0x1.6524f853b4aa3p-1},
    {0x1.0e117754d7c11p-1, 0x1.63356b88ac0dep-1}, {0x1.120f9d39e1807p-1, 0x1.614b36831ae94p-1},
    {0x1.160844495e006p-1, 0x1.5f66434292dfcp-1}, {0x1.19fb7b8f32421p-1, 0x1.5d867c3ece2a5p-1},
    {0x1.1de951d9cbba6p-1, 0x1.5babcc647fa91p-1}, {0x1.21d1d5bb6d59ap-1, 0x1.59d61f123ccaap-1},
    {0x1.25b5158b73d04p-1, 0x1.5805601580560p-1}, {0x1.29931f6791560p-1, 0x1.56397ba7c52e2p-1},
    {0x1.2d6c013501380p-1, 0x1.54725e6bb82fep-1}, {0x1.313fc8a1b36f2p-1, 0x1.52aff56a8054bp-1},
    {0x1.350e8325707d9p-1, 0x1.50f22e111c4c5p-1}, {0x1.38d83e02f5d09p-1, 0x1.4f38f62dd4c9bp-1},
    {0x1.3c9d06490ae12p-1, 0x1.4d843bedc2c4cp-1}, {0x1.405ce8d38f4bcp-1, 0x1.4bd3edda68fe1p-1},
    {0x1.4417f24c82165p-1, 0x1.4a27fad76014ap-1}, {0x1.47ce2f2d02587p-1, 0x1.4880522014880p-1},
    {0x1.4b7fabbe49795p-1, 0x1.46dce34596066p-1}, {0x1.4f2c741a9f33ep-1, 0x1.453d9e2c776cap-1},
    {0x1.52d4942e47909p-1, 0x1.43a2730abee4dp-1}, {0x1.567817b86b02cp-1, 0x1.420b5265e5951p-1},
    {0x1.5a170a4bf8d5cp-1, 0x1.40782d10e6566p-1}, {0x1.5db177508413cp-1, 0x1.3ee8f42a5af07p-1},
    {0x1.61476a031b109p-1, 0x1.3d5d991aa75c6p-1}, {0x1.64d8ed7719bf0p-1, 0x1.3bd60d9232955p-1},
    {0x1.68660c96f6f87p-1, 0x1.3a524387ac822p-1}, {0x1.6beed2250cdaep-1, 0x1.38d22d366088ep-1},
    {0x1.6f7348bc5c618p-1, 0x1.3755bd1c945eep-1}, {0x1.72f37ad14c5b0p-1, 0x1.35dce5f9f2af8p-1},
    {0x1.766f72b263deep-1, 0x1.34679ace01346p-1}, {0x1.79e73a8900620p-1, 0x1.32f5ced6a1dfap-1},
    {0x1.7d5adc5a078a4p-1, 0x1.3187758e9ebb6p-1}, {0x1.80ca620694df9p-1, 0x1.301c82ac40260p-1},
    {0x1.8435d54ca3774p-1, 0x1.2eb4ea1fed14bp-1}, {0x1.879d3fc7b3b71p-1, 0x1.2d50a012d50a0p-1},
    {0x1.8b00aaf16d4a9p-1, 0x1.2bef98e5a3711p-1}, {0x1.8e6020223d661p-1, 0x1.2a91c92f3c105p-1},
    {0x1.91bba891f1709p-1, 0x1.293725bb804a5p-1}, {0x1.95134d584e2e3p-1, 0x1.27dfa38a1ce4dp-1},
    {0x1.9867176da382fp-1, 0x1.268b37cd60127p-1}, {0x1.9bb70fab5ce4dp-1, 0x1.2539d7e9177b2p-1},
    {0x1.9f033ecc8e956p-1, 0x1.23eb79717605bp-1}, {0x1.a24bad6e7fb77p-1, 0x1.22a0122a0122ap-1},
    {0x1.a590641131564p-1, 0x1.21579804855e6p-1}, {0x1.a8d16b17e2745p-1, 0x1.2012012012012p-1},
    {0x1.ac0ecac99133bp-1, 0x1.1ecf43c7fb84cp-1}, {0x1.af488b51792d6p-1, 0x1.1d8f5672e4abdp-1},
    {0x1.b27eb4bf8f08ap-1, 0x1.1c522fc1ce059p-1}, {0x1.b5b14f08f9666p-1, 0x1.1b17c67f2bae3p-1},
    {0x1.b8e0620887309p-1, 0x1.19e0119e0119ep-1}, {0x1.bc0bf57f23606p-1, 0x1.18ab083902bdbp-1},
    {0x1.bf341114464a7p-1, 0x1.1778a191bd684p-1}, {0x1.c258bc5664829p-1, 0x1.1648d50fc3201p-1},
    {0x1.c579febb5b658p-1, 0x1.151b9a3fdd5c9p-1}, {0x1.c897dfa0db58ep-1, 0x1.13f0e8d344724p-1},
    {0x1.cbb2664ccfcf6p-1, 0x1.12c8b89edc0acp-1}, {0x1.cec999edc5203p-1, 0x1.11a3019a74826p-1},
    {0x1.d1dd819b4c3f1p-1, 0x1.107fbbe011080p-1}, {0x1.d4ee24565c62bp-1, 0x1.0f5edfab325a2p-1},
    {0x1.d7fb8909b2a6cp-1, 0x1.0e40655826011p-1}, {0x1.db05b68a2fb65p-1, 0x1.0d24456359e3ap-1},
    {0x1.de0cb397338a4p-1, 0x1.0c0a7868b4171p-1}, {0x1.e11086daf7496p-1, 0x1.0af2f722eecb5p-1},
    {0x1.e41136eae553dp-1, 0x1.09ddba6af8360p-1}, {0x1.e70eca47ef86fp-1, 0x1.08cabb37565e2p-1},
    {0x1.ea09475ee3c3ap-1, 0x1.07b9f29b8eae2p-1}, {0x1.ed00b488bec23p-1, 0x1.06ab59c7912fbp-1},
    {0x1.eff5180afd3e4p-1, 0x1.059eea0727586p-1}, {0x1.f2e67817eb845p-1, 0x1.04949cc1664c5p-1},
    {0x1.f5d4dacef36bep-1, 0x1.038c6b78247fcp-1}, {0x1.f8c0463ce8c69p-1, 0x1.02864fc7729e9p-1},
    {0x1.fba8c05c544dfp-1, 0x1.0182436517a37p-1}, {0x1.fe8e4f15bd1a0p-1, 0x1.0080402010080p-1},
};
