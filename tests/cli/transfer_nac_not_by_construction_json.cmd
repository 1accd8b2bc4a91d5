transfer tests/cli/transfer/forgetful_nac.cp --map ForgetHolders --problem Clear --plan tests/cli/transfer/discard.plan --no-timing --format json
